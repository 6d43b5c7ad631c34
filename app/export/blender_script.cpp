#include "app/export/blender_script.h"

#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/export/fit_report_json.h"
#include "app/material/material_json.h"
#include "app/text/numbers.h"

namespace skinlayer {
namespace {

std::string number(double value) { return text::format_shortest(value); }  // reads back to the last bit

std::string percent_triple(const Rgb& values) {
  char text[64];
  std::snprintf(text, sizeof text, "%.1f%% %.1f%% %.1f%%", 100.0 * values(0), 100.0 * values(1), 100.0 * values(2));
  return text;
}

// JSON in a Python raw string. JSON cannot hold three quotes in a row outside a string, and inside one each quote is
// escaped as \", which a raw string keeps for json.loads; ensure_ascii keeps the file ASCII.
std::string python_json(const nlohmann::ordered_json& json) {
  return "json.loads(r\"\"\"\n" + json.dump(2, ' ', true) + "\n\"\"\")";
}

std::string color(const Rgb& c, bool with_alpha) {
  std::ostringstream out;
  out << '(' << number(c(0)) << ", " << number(c(1)) << ", " << number(c(2)) << (with_alpha ? ", 1.0)" : ")");
  return out.str();
}

// The node's inputs by the names Blender 4.2-5.x gives them (node_shader_bsdf_principled.cc), those the fit sets.
// Diffuse Roughness, which 4.3 added, only where the fit uses it, so that 4.2 takes the rest.
std::string principled_inputs(const CyclesPrincipledParameters& p) {
  std::ostringstream out;
  out << "PRINCIPLED_INPUTS = {\n"
      << "    \"Base Color\": " << color(p.base_color, true) << ",\n"
      << "    \"Metallic\": " << number(p.metallic) << ",\n"
      << "    \"Roughness\": " << number(p.roughness) << ",\n"
      << "    \"IOR\": " << number(p.ior) << ",\n";
  if (p.diffuse_roughness > 0.0) out << "    \"Diffuse Roughness\": " << number(p.diffuse_roughness) << ",\n";
  out << "    \"Subsurface Weight\": " << number(p.subsurface_weight) << ",\n"
      << "    \"Subsurface Radius\": " << color(p.subsurface_radius, false) << ",\n"
      << "    \"Subsurface Scale\": " << number(p.subsurface_scale) << ",\n"
      << "    \"Subsurface Anisotropy\": " << number(p.subsurface_anisotropy) << ",\n"
      << "    \"Specular IOR Level\": " << number(p.specular_ior_level) << ",\n"
      << "    \"Specular Tint\": " << color(p.specular_tint, true) << ",\n"
      << "    \"Anisotropic\": " << number(p.anisotropic) << ",\n"
      << "    \"Transmission Weight\": " << number(p.transmission_weight) << ",\n"
      << "    \"Coat Weight\": " << number(p.coat_weight) << ",\n"
      << "    \"Coat Roughness\": " << number(p.coat_roughness) << ",\n"
      << "    \"Coat IOR\": " << number(p.coat_ior) << ",\n"
      << "    \"Coat Tint\": " << color(p.coat_tint, true) << ",\n"
      << "    \"Sheen Weight\": " << number(p.sheen_weight) << ",\n"
      << "    \"Sheen Roughness\": " << number(p.sheen_roughness) << ",\n"
      << "    \"Sheen Tint\": " << color(p.sheen_tint, true) << ",\n"
      << "}\n";
  return out.str();
}

// The node's inputs by the names Blender 3.4 gives them (node_shader_bsdf_principled.cc).
std::string principled_3_4_inputs(const PrincipledParameters& p) {
  std::ostringstream out;
  out << "PRINCIPLED_INPUTS = {\n"
      << "    \"Base Color\": (" << number(p.base_color(0)) << ", " << number(p.base_color(1)) << ", "
      << number(p.base_color(2)) << ", 1.0),\n"
      << "    \"Subsurface\": " << number(p.subsurface) << ",\n"
      << "    \"Subsurface Color\": (" << number(p.subsurface_color(0)) << ", " << number(p.subsurface_color(1)) << ", "
      << number(p.subsurface_color(2)) << ", 1.0),\n"
      << "    \"Subsurface Radius\": (" << number(p.subsurface_radius(0)) << ", " << number(p.subsurface_radius(1))
      << ", " << number(p.subsurface_radius(2)) << "),\n"
      << "    \"Subsurface Anisotropy\": " << number(p.subsurface_anisotropy) << ",\n"
      << "    \"Metallic\": " << number(p.metallic) << ",\n"
      << "    \"Specular\": " << number(p.specular) << ",\n"
      << "    \"Specular Tint\": " << number(p.specular_tint) << ",\n"
      << "    \"Roughness\": " << number(p.roughness) << ",\n"
      << "    \"Anisotropic\": " << number(p.anisotropic) << ",\n"
      << "    \"Sheen\": " << number(p.sheen) << ",\n"
      << "    \"Sheen Tint\": " << number(p.sheen_tint) << ",\n"
      << "    \"Clearcoat\": " << number(p.clearcoat) << ",\n"
      << "    \"Clearcoat Roughness\": " << number(p.clearcoat_roughness) << ",\n"
      << "    \"IOR\": " << number(p.ior) << ",\n"
      << "    \"Transmission\": " << number(p.transmission) << ",\n"
      << "    \"Transmission Roughness\": " << number(p.transmission_roughness) << ",\n"
      << "}\n";
  return out.str();
}

constexpr const char* kBuildMaterial = R"(

def check_blender_version():
    """Stops in a Blender whose Principled BSDF is not the one fitted: one line naming the export to make."""
    first, past = BLENDER_VERSIONS
    version = bpy.app.version
    if version >= first and (past is None or version < past):
        return
    if first >= (4, 0, 0) and (4, 0, 0) <= version < first:  # today's node, but older than this fit needs
        advice = "open it in Blender %d.%d or later" % first[:2]
    else:
        advice = f"make {OTHER_EXPORT} instead"
    message = (f"skinlayer: this script builds {NODE_NAME}, fitted for it; this is Blender "
               f"{bpy.app.version_string}: {advice}")
    if bpy.app.background:
        raise SystemExit(message)  # blender -b exits with status 1 and renders nothing
    raise RuntimeError(message)


def build_material(name=MATERIAL_NAME):
    """The fitted Principled BSDF as a new material; returns it."""
    material = bpy.data.materials.new(name)
    if bpy.app.version < (5, 0, 0):  # 5.x makes every material with nodes, and deprecates use_nodes
        material.use_nodes = True
    nodes = material.node_tree.nodes
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    output.location = (300, 0)
    principled = nodes.new("ShaderNodeBsdfPrincipled")
    principled.distribution = DISTRIBUTION  # as fitted
    for socket, value in PRINCIPLED_INPUTS.items():
        principled.inputs[socket].default_value = value
    material.node_tree.links.new(principled.outputs["BSDF"], output.inputs["Surface"])
    material["skinlayer_material"] = json.dumps(SKINLAYER_MATERIAL)
    material["skinlayer_fit"] = json.dumps(SKINLAYER_FIT)
    return material


def build_preview_scene(material):
    """Replaces the scene's objects with a unit sphere wearing `material`, an orthographic camera on +z looking
    down -z, a sun from the upper left and a dim grey world; Cycles on the CPU, linear Standard view."""
    scene = bpy.context.scene
    for obj in list(scene.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    bpy.ops.mesh.primitive_uv_sphere_add(segments=256, ring_count=128, radius=1.0, location=(0.0, 0.0, 0.0))
    sphere = bpy.context.object
    sphere.name = "skinlayer sphere"
    for polygon in sphere.data.polygons:
        polygon.use_smooth = True
    sphere.data.materials.append(material)

    camera = bpy.data.objects.new("skinlayer camera", bpy.data.cameras.new("skinlayer camera"))
    camera.data.type = "ORTHO"
    camera.data.ortho_scale = 2.2
    camera.location = (0.0, 0.0, 10.0)
    scene.collection.objects.link(camera)
    scene.camera = camera

    sun = bpy.data.objects.new("skinlayer sun", bpy.data.lights.new("skinlayer sun", type="SUN"))
    sun.data.energy = 3.0  # irradiance on a face turned to it, W/m^2
    sun.data.angle = 0.0
    sun.rotation_euler = (math.radians(-35.0), math.radians(-35.0), 0.0)  # from the upper left, toward the viewer
    scene.collection.objects.link(sun)

    world = scene.world or bpy.data.worlds.new("skinlayer world")
    scene.world = world
    if bpy.app.version < (5, 0, 0):
        world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.05, 0.05, 0.05, 1.0)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 1.0

    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 128
    scene.cycles.use_denoising = False  # Debian's Blender 3.4 and 4.3 are built without OpenImageDenoise
    scene.render.resolution_x = scene.render.resolution_y = 512
    scene.render.resolution_percentage = 100
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    return sphere


check_blender_version()
material = build_material()
if BUILD_SCENE:
    build_preview_scene(material)
)";

// What a script is for: the node's name, the Blender versions [first, past) that have it, its distribution and the
// export to make in another Blender.
struct NodeTarget {
  const char* node_name;
  const char* first_version;  // a Python tuple
  const char* past_version;   // a Python tuple, or None
  const char* distribution;
  const char* other_export;
};

// The script around the node's inputs: its header (`lost`: what the fit loses, as comment lines), the fit's report
// and the material as Python data, and the code that builds them.
std::string script(const MaterialDocument& document, const NodeTarget& target, const nlohmann::ordered_json& report,
                   const FitErrors& errors, bool albedo_matched, const std::string& lost, const std::string& inputs,
                   const BlenderScriptSettings& settings) {
  const std::string name = document.name.empty() ? "skinlayer material" : "skinlayer " + document.name;
  std::ostringstream out;
  out << "# " << target.node_name << " fitted by skinlayer to the material " << nlohmann::json(name).dump(-1, ' ', true)
      << ".\n"
      << "# Run: blender -b --python-exit-code 1 --python THIS.py  (add -o //preview_#### -f 1 to render, with "
         "--scene's\n"
      << "# preview). In another Blender than " << target.node_name << "'s it stops with one line.\n"
      << "#\n"
      << "# The fit's error, red green blue, relative to the material's own values (skinlayer fit --help):\n"
      << "#   cosine-weighted BRDF, light 0-80 degrees   RMS " << percent_triple(errors.lobe_rms) << "   worst "
      << percent_triple(errors.lobe_worst) << "\n"
      << "#   directional albedo, 0-80 degrees           RMS " << percent_triple(errors.albedo_rms) << "   worst "
      << percent_triple(errors.albedo_worst) << "\n"
      << "# The albedo at normal incidence is the material's" << (albedo_matched ? "" : ", but where it could not be")
      << ".\n"
      << lost << "import json\n"
      << "import math\n\n"
      << "import bpy\n\n"
      << "MATERIAL_NAME = " << nlohmann::json(name).dump(-1, ' ', true) << "\n"
      << "BUILD_SCENE = " << (settings.scene ? "True" : "False") << "\n"
      << "NODE_NAME = " << nlohmann::json(target.node_name).dump() << "\n"
      << "BLENDER_VERSIONS = (" << target.first_version << ", " << target.past_version << ")  # [first, past)\n"
      << "DISTRIBUTION = \"" << target.distribution << "\"\n"
      << "OTHER_EXPORT = " << nlohmann::json(target.other_export).dump() << "\n"
      << "SKINLAYER_MATERIAL = " << python_json(material_json(document)) << "\n"
      << "SKINLAYER_FIT = " << python_json(report) << "\n"
      << inputs << kBuildMaterial;
  return out.str();
}

}  // namespace

std::string blender_script(const MaterialDocument& document, const DocumentFit<CyclesPrincipledFit>& report,
                           const BlenderScriptSettings& settings) {
  const CyclesPrincipledFit& fit = report.fit;
  const bool diffuse_roughness = fit.parameters.diffuse_roughness > 0.0;
  const NodeTarget target{diffuse_roughness ? "the Principled BSDF of Blender 4.3 and later"
                                            : "the Principled BSDF of Blender 4.2 and later",
                          diffuse_roughness ? "(4, 3, 0)" : "(4, 2, 0)", "None", "MULTI_GGX",
                          "`skinlayer export --format blender-3.4` for Blender 3.x"};
  const std::string lost =
      "# Lost in the fit: the subsurface lobe's shape beyond the node's diffuse and sheen; a rough interface's\n"
      "# Beckmann tail (GGX's is longer); light through the layer (the material is opaque here).\n"
      "# Subsurface Weight stays 0, as fitted; radius, scale and anisotropy are set (" +
      report.radius_source + ").\n# Raised, it gives translucency.\n";
  return script(document, target, principled_fit_json(report), fit.errors, fit.albedo_matched, lost,
                principled_inputs(fit.parameters), settings);
}

std::string blender_3_4_script(const MaterialDocument& document, const DocumentFit<PrincipledFit>& report,
                               const BlenderScriptSettings& settings) {
  const PrincipledFit& fit = report.fit;
  const NodeTarget target{"Blender 3.4's Principled BSDF", "(3, 0, 0)", "(4, 0, 0)", "GGX",
                          "`skinlayer export --format blender` for Blender 4.2 and later"};
  const std::string lost =
      "# Lost in the fit: the subsurface lobe's shape beyond Burley's diffuse, sheen and retro-reflection; a rough\n"
      "# interface's Beckmann tail (GGX's is longer); light through the layer (the material is opaque here).\n"
      "# Subsurface stays 0, as fitted; its colour and radius are set (radius: " +
      report.radius_source +
      ").\n# Raised, it gives translucency, and Cycles' random walk renders 2-5% brighter than the fit (measured).\n";
  return script(document, target, principled_3_4_fit_json(report), fit.errors, fit.albedo_matched, lost,
                principled_3_4_inputs(fit.parameters), settings);
}

}  // namespace skinlayer
