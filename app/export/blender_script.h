// Python scripts for Blender that build a fitted Principled BSDF as a material: what `skinlayer export --format
// blender` (Blender 4.2 to 5.x, core/fit/cycles_principled_fit.h) and `--format blender-3.4` (Blender 3.x,
// core/fit/principled_fit.h) write. Run one with `blender -b --python-exit-code 1 --python FILE.py` (then render or
// save in the same call: `-o //preview_#### -f 1`), or from Blender's Text Editor.
//
// Blender 4.0 rebuilt the node: its inputs, lobes and layering differ, so a fit is made for one node. Each script
// first checks bpy.app.version against the Blender its node belongs to, and in another Blender stops with one line
// that names the export to make instead: under `blender -b` it exits with status 1 (SystemExit), so nothing renders;
// in Blender's window it raises an error. Today's script needs 4.3 where the fit uses Diffuse Roughness (which 4.3
// added), 4.2 otherwise (4.0 and 4.1 estimated the layers' albedos otherwise: closure/bsdf_microfacet.h).
//
// The script sets every input the fit chose and the node's distribution: "Multiscatter GGX" for today's node (its
// default, which Cycles 4.x evaluates in closed form), "GGX" for 3.4's (single scattering; 3.4's "Multiscatter GGX" is
// a stochastic walk the fit cannot model). The subsurface radius (and in 4.x its scale) is set with the weight at
// 0 as fitted: raising it gives translucency. It carries skinlayer's material (the material file's JSON) and the
// fit's report (parameters and errors) as Python data, and stores both on the material as custom properties
// ("skinlayer_material", "skinlayer_fit"), so they travel in the .blend file. With `scene`, it also replaces the
// scene with a preview: a unit sphere at the origin (256 x 128 UV sphere, smooth shaded) under an orthographic camera
// on +z looking down -z (ortho scale 2.2), a sun from the upper left, a dim grey world, and Cycles on the CPU (no
// denoising: Debian's Blender 3.4 and 4.3 have no OpenImageDenoise) with the "Standard" view. It uses no API that
// Blender 5.x marks for removal (Material.use_nodes and World.use_nodes are set only before 5.0).
#pragma once

#include <string>

#include "app/material/material_document.h"
#include "app/solution/principled_fit_document.h"
#include "app/solution/shader_fit.h"

namespace skinlayer {

struct BlenderScriptSettings {
  bool scene = false;  // also build the preview scene
};

// The scripts' text. `document` is the material that was fitted.
std::string blender_script(const MaterialDocument& document, const DocumentFit<CyclesPrincipledFit>& fit,
                           const BlenderScriptSettings& settings);
std::string blender_3_4_script(const MaterialDocument& document, const DocumentFit<PrincipledFit>& fit,
                               const BlenderScriptSettings& settings);

}  // namespace skinlayer
