#include "app/cli/render_command.h"

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/environment_flags.h"
#include "app/cli/errors.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/model_flag.h"
#include "app/cli/skin_flag.h"
#include "app/gl/osmesa_context.h"
#include "app/material/atomic_file.h"
#include "app/material/picture_metadata.h"
#include "app/process/parallel_for.h"
#include "app/render/environment_map.h"
#include "app/render/hdr_export.h"
#include "app/render/png_export.h"
#include "app/render/render_target.h"
#include "app/render/scene.h"
#include "app/render/table_textures.h"
#include "app/solution/material_solve.h"
#include "app/solution/sphere_spread.h"
#include "app/text/numbers.h"
#include "app/text/quoted.h"
#include "core/conventions.h"

namespace skinlayer::cli {
namespace {

constexpr int kMaxSide = 8192;

std::pair<int, int> parse_size(std::string_view text) {
  const std::size_t x = text.find('x');
  const std::optional<double> w = text::parse_number(text.substr(0, x));
  const std::optional<double> h = x == std::string_view::npos ? std::nullopt : text::parse_number(text.substr(x + 1));
  if (!w || !h || *w != static_cast<int>(*w) || *h != static_cast<int>(*h) || *w < 16 || *h < 16 || *w > kMaxSide ||
      *h > kMaxSide) {
    throw UsageError("size = " + text::quoted(text) + " must be WIDTHxHEIGHT in pixels, each a whole number in [16, " +
                     std::to_string(kMaxSide) + "], as in --size 1024x512");
  }
  return {static_cast<int>(*w), static_cast<int>(*h)};
}

ViewKind parse_view(std::string_view text) {
  const std::optional<ViewKind> view = parse_view_kind(text);
  if (!view) throw UsageError("view = " + text::quoted(text) + " is not one of sphere, polar, both, compare");
  return *view;
}

}  // namespace

std::string render_usage() {
  return "Usage: skinlayer render [material flags] [--albedo A | r,g,b] [--model M] [--light-theta D] [--light-phi D]\n"
         "                        [--view sphere|polar|both] [--size WxH] [--exposure E] [--scale linear|log]\n"
         "                        [--env E [--env-rotate DEG] [--env-ev EV] [--background B] [--samples N]]\n"
         "                        [--light on|off] [--tonemap T] -o FILE.png|FILE.hdr\n"
         "\n"
         "Renders the previewer's picture offscreen (OSMesa, no display needed) with the same renderer as the\n"
         "window and writes it as PNG, or as linear radiance without a tone map (.hdr, --view sphere).\n" +
         rgb_albedo_usage() +
         "  --model M            subsurface model: stam (default), lambert or hk (Hanrahan-Krueger)\n"
         "  --light-theta D      light angle from the view direction, degrees in [0, 89.9] (default 45)\n"
         "  --light-phi D        light azimuth in the picture plane, degrees (default 180: from the left)\n"
         "  --view V             sphere, polar (lobes in the plane of incidence), both, or compare: three\n"
         "                       spheres, Lambert | Hanrahan-Krueger | the layer model (default both)\n"
         "  --size WxH           pixels (default 1024x512 for both, 1200x400 for compare, 512x512 otherwise)\n"
         "  --exposure E         linear exposure before the exponential tone map, in (0, 1000] (default 1)\n"
         "  --scale S            lobe radius linear or log (3 decades) (default linear)\n"
         "  -o, --output FILE    the picture to write (required): .png, or .hdr for linear radiance\n"
         "  --sphere-radius MM   a sphere of this radius in mm, in [0.1, 10000], whose subsurface light spreads by\n"
         "                       the material's profile (skinlayer profile), bleeding past the terminator; the\n"
         "                       material needs a profile and lengths (mu_t; a skin has them). A skin takes about\n"
         "                       5 s on two cores. Without it the light leaves where it falls.\n" +
         lighting_flags_usage() + "\n" +
         "A --skin renders its spectrum's linear sRGB (CIE 1931 2-degree, D65); --wavelength NM one wavelength's\n"
         "grey material.\n" +
         skin_flags_usage() + "\n" + material_flags_usage();
}

int run_render_command(std::span<const std::string_view> arguments, std::ostream& out, std::ostream& progress) {
  std::vector<std::string_view> known =
      material_flags_and({kModelFlag, kSkinFlag, kWavelengthFlag, "light-theta", "light-phi", "view", "size",
                          "exposure", "scale", "output", "sphere-radius"});
  for (std::string_view name : lighting_flag_names()) known.push_back(name);
  const ParsedFlags flags = ParsedFlags::parse(arguments, known, "skinlayer render");
  MaterialDocument document = material_document_from_flags(flags, AlbedoFlag::GreyOrRgb);
  if (const std::optional<double> wavelength = wavelength_from_flags(flags)) {
    document = document_at_wavelength(document, *wavelength);
  }
  ColorMaterial material = color_material(document);
  material.model = model_from_flags(flags, document.model);
  const std::optional<std::string_view> output = flags.value("output");
  if (!output) throw UsageError("render needs -o FILE.png (the picture to write)");
  const ViewKind view = parse_view(flags.value("view").value_or("both"));
  const std::string_view default_size = view == ViewKind::Both      ? "1024x512"
                                        : view == ViewKind::Compare ? "1200x400"
                                                                    : "512x512";
  const auto [width, height] = parse_size(flags.value("size").value_or(default_size));
  const double light_theta = degrees_to_radians(number_flag(flags, "light-theta", 45.0, 0.0, 89.9, " (degrees)"));
  const double light_phi = degrees_to_radians(number_flag(flags, "light-phi", 180.0, -360.0, 360.0, " (degrees)"));
  const double exposure = number_flag(flags, "exposure", 1.0, 1e-6, 1000.0, "");
  const std::string_view scale = flags.value("scale").value_or("linear");
  if (scale != "linear" && scale != "log") throw UsageError("scale = " + text::quoted(scale) + " is not linear or log");
  const LightingFlags lighting = lighting_from_flags(flags);
  const bool hdr = output->ends_with(".hdr");
  if (!hdr && !output->ends_with(".png")) {
    throw UsageError("output = " + text::quoted(*output) +
                     ": render writes PNG (.png) or Radiance HDR (.hdr) pictures; give a name ending in one of them");
  }
  if (hdr && view != ViewKind::Sphere) {
    throw UsageError("a .hdr picture holds the sphere's linear radiance: give --view sphere");
  }
  if (lighting.environment && view == ViewKind::Compare) {
    throw UsageError("--env with --view compare is not supported: the three spheres would need three estimates");
  }
  // The environment is read before the solve, so that a bad file is found at once.
  const std::optional<EnvironmentMap> environment =
      lighting.environment ? std::optional<EnvironmentMap>(load_environment(*lighting.environment)) : std::nullopt;

  SolveOptions solve_options;  // the RGB channels side by side
  solve_options.parallel_for = parallel_for_threads;
  const ColorTables tables = solve_color(material, light_theta, solve_options);
  gl::OsmesaContext context(width, height);
  Renderer renderer;
  renderer.upload(make_table_textures(tables));
  if (view == ViewKind::Compare) {  // every model to its slot; the material's own model is already solved
    for (std::size_t k = 0; k < kCompareSlots.size(); ++k) {
      ColorMaterial compared = material;
      compared.model = kCompareModels[k];
      const ColorTables solved =
          compared.model == material.model ? tables : solve_color(compared, light_theta, solve_options);
      renderer.upload(make_table_textures(solved), kCompareSlots[k]);
    }
  }
  Scene scene = make_scene(tables, view, light_theta, light_phi, exposure, scale == "log");
  std::optional<double> sphere_radius;
  if (flags.has("sphere-radius")) {
    sphere_radius = number_flag(flags, "sphere-radius", 40.0, 0.1, 10000.0, " (mm)");
    progress << "render: the material's profile, for the sphere's translucency\n" << std::flush;
    const SpreadProfile profile = spread_profile(document, false, parallel_for_threads);
    renderer.upload_spread(spread_texture(profile, *sphere_radius));
    scene.sphere.spread = true;
  }
  scene.sphere.tone_map = lighting.tone_map;
  scene.sphere.linear_output = hdr;
  if (!lighting.directional_light) scene.sphere.irradiance = 0.0;
  std::optional<EnvironmentAccumulation> accumulation;
  if (environment) {
    renderer.upload_environment(*environment);
    scene.sphere.environment = lighting.view;
    const Viewport sphere = scene_viewports(view, width, height).front();
    accumulation.emplace(sphere.width, sphere.height);
    constexpr int kPerPass = 8;  // a pass of 512 x 512 at 8 samples: ~0.1-0.2 s under llvmpipe
    int reported = 0;
    while (accumulation->samples() < lighting.samples) {
      renderer.accumulate_environment(*accumulation, lighting.view, scene.surface,
                                      std::min(kPerPass, lighting.samples - accumulation->samples()));
      glFinish();
      const int tenths = 10 * accumulation->samples() / lighting.samples;
      if (tenths > reported) {
        reported = tenths;
        progress << "render: " << accumulation->samples() << " of " << lighting.samples << " samples per pixel\n"
                 << std::flush;
      }
    }
  }
  RenderTarget target(width, height, hdr ? PixelFormat::Rgba32F : PixelFormat::Rgba8);
  target.bind();
  draw_scene(renderer, scene, width, height, accumulation ? &*accumulation : nullptr);
  RenderTarget::unbind();
  if (hdr) {
    write_file_atomically(std::string(*output), encode_hdr(width, height, target.read_rgba32f()));
    out << "wrote " << *output << " (" << width << "x" << height << ", linear radiance)\n";
    return kExitSuccess;
  }
  MaterialDocument drawn = document;
  drawn.model = material.model;
  nlohmann::ordered_json settings = {{"command", "render"},
                                     {"view", std::string(flags.value("view").value_or("both"))},
                                     {"size", {width, height}},
                                     {"light_theta", radians_to_degrees(light_theta)},
                                     {"light_phi", radians_to_degrees(light_phi)},
                                     {"exposure", exposure},
                                     {"scale", std::string(scale)}};
  if (sphere_radius) settings["sphere_radius_mm"] = *sphere_radius;
  if (lighting.environment) {
    settings["environment"] = {{"source", *lighting.environment},
                               {"rotate", radians_to_degrees(lighting.view.rotation)},
                               {"ev", std::log2(lighting.view.scale)},
                               {"background", kBackgroundNames[static_cast<std::size_t>(lighting.view.background)]},
                               {"samples", lighting.samples},
                               {"light", lighting.directional_light}};
  }
  settings["tonemap"] = kToneMapNames[static_cast<std::size_t>(lighting.tone_map)];
  write_png(Image{width, height, target.read_rgba8()}, std::string(*output), {picture_metadata(drawn, settings)});
  out << "wrote " << *output << " (" << width << "x" << height << ")\n";
  return kExitSuccess;
}

}  // namespace skinlayer::cli
