// A Python script for Blender 3.4 that builds a fitted Principled BSDF (core/fit/principled_fit.h) as a material:
// what `skinlayer export --format blender` writes. Run it with `blender -b --python FILE.py` (then render or save in
// the same call: `-o //preview_#### -f 1`), or from Blender's Text Editor.
//
// The script sets every Principled input the fit chose and the node's "GGX" distribution (the single-scattering
// lobe the fit is made for; Blender's default, "Multiscatter GGX", is brighter at high roughness). The subsurface
// colour and radius are set, with the weight at 0 as fitted: raising it gives translucency, and in Cycles 3.4's
// random walk a BRDF 2-5% brighter than the fit's (measured). It carries
// skinlayer's material (the material file's JSON) and the fit's report (parameters and errors) as Python data, and
// stores both on the material as custom properties ("skinlayer_material", "skinlayer_fit"), so they travel in the
// .blend file. With `scene`, it also replaces the scene with a preview: a unit sphere at the origin (256 x 128 UV
// sphere, smooth shaded) under an orthographic camera on +z looking down -z (ortho scale 2.2), a sun from the upper
// left, a dim grey world, and Cycles on the CPU (no denoising: Debian 12's Blender has no OpenImageDenoise) with the
// "Standard" view.
#pragma once

#include <string>

#include "app/material/material_document.h"
#include "app/solution/shader_fit.h"

namespace skinlayer {

struct BlenderScriptSettings {
  bool scene = false;  // also build the preview scene
};

// The script's text. `document` is the material that was fitted.
std::string blender_script(const MaterialDocument& document, const DocumentFit<PrincipledFit>& fit,
                           const BlenderScriptSettings& settings);

}  // namespace skinlayer
