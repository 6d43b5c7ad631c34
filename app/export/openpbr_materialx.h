// A fitted OpenPBR Surface (core/fit/openpbr_fit.h) as a MaterialX 1.39 document: what `skinlayer export --format
// mtlx` writes, for Maya, Arnold, 3ds Max, Houdini and Unreal, which read OpenPBR through MaterialX. Written with
// pugixml, never by hand. The document holds
//   <materialx version="1.39" colorspace="lin_rec709">       (skinlayer's colours are linear sRGB)
//     <open_pbr_surface name="SR_<name>" type="surfaceshader" doc="<the fit's report, JSON>">
//       <input name="..." type="float|color3" value="..."/>   (each input the fit sets; subsurface_radius with
//                                                               unittype="distance" unit="millimeter")
//     <surfacematerial name="<name>" type="material" doc="skinlayer <the material file's JSON>">
//       <input name="surfaceshader" type="surfaceshader" nodename="SR_<name>"/>
// <name> is the material's name made a MaterialX identifier (letters, digits and underscores, not starting with a
// digit). The node definition it is checked against ships in tests/reference/openpbr (tests/app/export).
#pragma once

#include <string>

#include "app/material/material_document.h"
#include "app/solution/shader_fit.h"

namespace skinlayer {

std::string openpbr_materialx(const MaterialDocument& document, const DocumentFit<OpenPbrFit>& fit);

// The identifier MaterialX names take for a material's name ("skin-fair" -> "skin_fair"; empty -> "skinlayer").
std::string materialx_identifier(const std::string& name);

}  // namespace skinlayer
