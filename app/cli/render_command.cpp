#include "app/cli/render_command.h"

#include <optional>
#include <string>
#include <vector>

#include "app/cli/errors.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/model_flag.h"
#include "app/cli/numbers.h"
#include "app/cli/quoted.h"
#include "app/gl/osmesa_context.h"
#include "app/process/parallel_for.h"
#include "app/render/material_solve.h"
#include "app/render/png_export.h"
#include "app/render/render_target.h"
#include "app/render/scene.h"
#include "app/render/table_textures.h"
#include "core/conventions.h"

namespace skinlayer::cli {
namespace {

constexpr int kMaxSide = 8192;

double number_in(const ParsedFlags& flags, std::string_view name, double fallback, double low, double high,
                 std::string_view unit) {
  const std::optional<std::string_view> text = flags.value(name);
  if (!text) return fallback;
  const std::optional<double> value = parse_number(*text);
  if (!value || !(*value >= low && *value <= high)) {
    throw UsageError(std::string(name) + " = " + quoted(*text) + " is out of range; valid range is [" +
                     format_short(low) + ", " + format_short(high) + "]" + std::string(unit));
  }
  return *value;
}

// "A" or "r,g,b", each a single-scattering albedo in [0, 1] (core's range check names the parameter).
std::array<double, 3> parse_albedo(std::string_view text) {
  std::array<double, 3> rgb{};
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    parts.push_back(text.substr(start, comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (parts.size() != 1 && parts.size() != 3) {
    throw UsageError("albedo = " + quoted(text) + " must be one number or three (r,g,b), each in [0, 1]");
  }
  for (std::size_t c = 0; c < 3; ++c) {
    const std::string_view part = parts[parts.size() == 1 ? 0 : c];
    const std::optional<double> value = parse_number(part);
    if (!value) throw UsageError("albedo = " + quoted(text) + ": " + quoted(part) + " " + number_rejection(part));
    check_parameter(parameter_info("albedo"), *value);
    rgb[c] = *value;
  }
  return rgb;
}

std::pair<int, int> parse_size(std::string_view text) {
  const std::size_t x = text.find('x');
  const std::optional<double> w = parse_number(text.substr(0, x));
  const std::optional<double> h = x == std::string_view::npos ? std::nullopt : parse_number(text.substr(x + 1));
  if (!w || !h || *w != static_cast<int>(*w) || *h != static_cast<int>(*h) || *w < 16 || *h < 16 || *w > kMaxSide ||
      *h > kMaxSide) {
    throw UsageError("size = " + quoted(text) + " must be WIDTHxHEIGHT in pixels, each a whole number in [16, " +
                     std::to_string(kMaxSide) + "], as in --size 1024x512");
  }
  return {static_cast<int>(*w), static_cast<int>(*h)};
}

ViewKind parse_view(std::string_view text) {
  const std::optional<ViewKind> view = parse_view_kind(text);
  if (!view) throw UsageError("view = " + quoted(text) + " is not one of sphere, polar, both, compare");
  return *view;
}

}  // namespace

std::string render_usage() {
  return "Usage: skinlayer render [material flags] [--albedo A | r,g,b] [--model M] [--light-theta D] [--light-phi D]\n"
         "                        [--view sphere|polar|both] [--size WxH] [--exposure E] [--scale linear|log]\n"
         "                        -o FILE.png\n"
         "\n"
         "Renders the previewer's picture offscreen (OSMesa, no display needed) with the same renderer as the\n"
         "window and writes it as PNG.\n"
         "  --albedo A | r,g,b   single-scattering albedo, grey or per color channel, each in [0, 1] (default 1)\n"
         "  --model M            subsurface model: stam (default), lambert or hk (Hanrahan-Krueger)\n"
         "  --light-theta D      light angle from the view direction, degrees in [0, 89.9] (default 45)\n"
         "  --light-phi D        light azimuth in the picture plane, degrees (default 180: from the left)\n"
         "  --view V             sphere, polar (lobes in the plane of incidence), both, or compare: three\n"
         "                       spheres, Lambert | Hanrahan-Krueger | the layer model (default both)\n"
         "  --size WxH           pixels (default 1024x512 for both, 1200x400 for compare, 512x512 otherwise)\n"
         "  --exposure E         linear exposure before the exponential tone map, in (0, 1000] (default 1)\n"
         "  --scale S            lobe radius linear or log (3 decades) (default linear)\n"
         "  -o, --output FILE    the PNG to write (required)\n"
         "\n" +
         material_flags_usage();
}

int run_render_command(std::span<const std::string_view> arguments, std::ostream& out) {
  // An "--albedo r,g,b" is read here; the material parser is given its red channel (parse_albedo has validated all
  // three).
  std::array<double, 3> albedo_rgb = {1.0, 1.0, 1.0};
  std::string red;
  std::vector<std::string_view> rewritten;
  for (std::size_t k = 0; k < arguments.size(); ++k) {
    const std::string_view argument = arguments[k];
    std::optional<std::string_view> albedo_text;
    if (argument == "--albedo" && k + 1 < arguments.size()) {
      albedo_text = arguments[++k];
    } else if (argument.starts_with("--albedo=")) {
      albedo_text = argument.substr(std::string_view("--albedo=").size());
    }
    if (albedo_text) {
      albedo_rgb = parse_albedo(*albedo_text);
      red = format_number(albedo_rgb[0]);
      rewritten.insert(rewritten.end(), {"--albedo", red});
    } else {
      rewritten.push_back(argument);
    }
  }
  const std::vector<std::string_view> known =
      material_flags_and({kModelFlag, "light-theta", "light-phi", "view", "size", "exposure", "scale", "output"});
  const ParsedFlags flags = ParsedFlags::parse(rewritten, known, "skinlayer render");
  ColorMaterial material{material_from_flags(flags), albedo_rgb, model_from_flags(flags)};
  const std::optional<std::string_view> output = flags.value("output");
  if (!output) throw UsageError("render needs -o FILE.png (the picture to write)");
  const ViewKind view = parse_view(flags.value("view").value_or("both"));
  const std::string_view default_size = view == ViewKind::Both      ? "1024x512"
                                        : view == ViewKind::Compare ? "1200x400"
                                                                    : "512x512";
  const auto [width, height] = parse_size(flags.value("size").value_or(default_size));
  const double light_theta = degrees_to_radians(number_in(flags, "light-theta", 45.0, 0.0, 89.9, " (degrees)"));
  const double light_phi = degrees_to_radians(number_in(flags, "light-phi", 180.0, -360.0, 360.0, " (degrees)"));
  const double exposure = number_in(flags, "exposure", 1.0, 1e-6, 1000.0, "");
  const std::string_view scale = flags.value("scale").value_or("linear");
  if (scale != "linear" && scale != "log") throw UsageError("scale = " + quoted(scale) + " is not linear or log");

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
  const Scene scene = make_scene(tables, view, light_theta, light_phi, exposure, scale == "log");
  RenderTarget target(width, height, PixelFormat::Rgba8);
  target.bind();
  draw_scene(renderer, scene, width, height);
  RenderTarget::unbind();
  write_png(Image{width, height, target.read_rgba8()}, std::string(*output));
  out << "wrote " << *output << " (" << width << "x" << height << ")\n";
  return kExitSuccess;
}

}  // namespace skinlayer::cli
