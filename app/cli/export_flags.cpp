#include "app/cli/export_flags.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

#include "app/cli/errors.h"
#include "app/text/numbers.h"
#include "app/text/quoted.h"

namespace skinlayer::cli {
namespace {

constexpr std::array<std::string_view, 3> kExportFlags = {"format", "nodes", "resolution"};
constexpr std::array<std::string_view, 2> kExportSwitches = {"rgb", "scene"};

int parse_nodes(std::optional<std::string_view> text) {
  if (!text) return kDefaultScatfunNodes;
  const std::optional<double> value = text::parse_number(*text);
  if (!value || *value != std::floor(*value) || *value < kMinScatfunNodes || *value > kMaxScatfunNodes) {
    throw UsageError("nodes = " + text::quoted(*text) + " must be a whole number in [" +
                     std::to_string(kMinScatfunNodes) + ", " + std::to_string(kMaxScatfunNodes) +
                     "] (polar nodes per hemisphere)");
  }
  return static_cast<int>(*value);
}

int parse_resolution(std::optional<std::string_view> text) {
  if (!text) return RglOptions{}.samples;
  const std::optional<double> value = text::parse_number(*text);
  if (!value || *value != std::floor(*value) || *value < RglOptions::kMinSamples || *value > RglOptions::kMaxSamples) {
    throw UsageError("resolution = " + text::quoted(*text) + " must be a whole number in [" +
                     std::to_string(RglOptions::kMinSamples) + ", " + std::to_string(RglOptions::kMaxSamples) +
                     "] (sample nodes per side of an RGL slice)");
  }
  return static_cast<int>(*value);
}

}  // namespace

std::span<const std::string_view> export_flag_names() { return kExportFlags; }
std::span<const std::string_view> export_switch_names() { return kExportSwitches; }

ExportRequest export_request_from_flags(const ParsedFlags& flags) {
  const std::optional<std::string_view> format = flags.value("format");
  if (!format) {
    throw UsageError("export needs --format bsdf, merl, rgl, blender, blender-3.4, mtlx or gltf (the format to write)");
  }
  static constexpr std::array<std::pair<std::string_view, FittedFormat>, 4> kFitted = {
      {{"blender", FittedFormat::BlenderScript},
       {"blender-3.4", FittedFormat::BlenderScript34},
       {"mtlx", FittedFormat::MaterialX},
       {"gltf", FittedFormat::Gltf}}};
  const auto fitted_format =
      std::find_if(kFitted.begin(), kFitted.end(), [&](const auto& f) { return f.first == *format; });
  if (*format != "merl" && *format != "bsdf" && *format != "rgl" && fitted_format == kFitted.end())
    throw UsageError("format = " + text::quoted(*format) +
                     " is not one of: bsdf, merl, rgl, blender, blender-3.4, mtlx, gltf");
  const bool bsdf = *format == "bsdf", rgl = *format == "rgl";
  const bool blender = *format == "blender" || *format == "blender-3.4";
  if (!blender && flags.has("scene")) throw UsageError("--scene is for --format blender or blender-3.4");
  if (fitted_format != kFitted.end()) {
    for (const std::string_view tabulated : {"nodes", "resolution", "rgb"}) {
      if (flags.has(tabulated)) {
        throw UsageError("--" + std::string(tabulated) + " is for the tabulated formats, not --format " +
                         std::string(*format));
      }
    }
    FittedExportSettings fitted;
    fitted.format = fitted_format->second;
    fitted.scene = flags.has("scene");
    return fitted;
  }
  if (!rgl && flags.has("rgb")) throw UsageError("--rgb is for --format rgl");
  if (!rgl && flags.has("resolution")) throw UsageError("--resolution is for --format rgl (--nodes for bsdf)");
  ExportSettings settings;
  settings.rgl.samples = parse_resolution(flags.value("resolution"));
  if (!bsdf && flags.has("nodes")) throw UsageError("--nodes is for --format bsdf (a MERL file's bins are fixed)");
  settings.format = bsdf               ? TabulatedFormat::Scatfun
                    : !rgl             ? TabulatedFormat::Merl
                    : flags.has("rgb") ? TabulatedFormat::RglRgb
                                       : TabulatedFormat::RglSpectral;
  settings.nodes = bsdf ? parse_nodes(flags.value("nodes")) : kDefaultScatfunNodes;
  return settings;
}

std::optional<std::string> missing_output_folder(const std::string& path) {
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (folder.empty() || std::filesystem::is_directory(folder)) return std::nullopt;
  return "cannot write " + path + ": no folder " + folder.string();
}

}  // namespace skinlayer::cli
