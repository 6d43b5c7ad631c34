#include "app/cli/profile_command.h"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/errors.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/numeric_table.h"
#include "app/cli/skin_flag.h"
#include "app/process/parallel_for.h"
#include "app/solution/document_profile.h"
#include "app/text/numbers.h"
#include "app/text/quoted.h"

namespace skinlayer::cli {
namespace {

constexpr std::string_view kIncidenceFlag = "incidence";
constexpr std::string_view kAnnuliFlag = "annuli";
constexpr std::string_view kRadiiFlag = "radii";
constexpr int kMaxAnnuli = 10000;

double positive_number(std::string_view flag, std::string_view text) {
  const std::optional<double> value = text::parse_number(text);
  if (!value || !(*value > 0.0) || !std::isfinite(*value)) {
    throw UsageError(std::string(flag) + " = " + text::quoted(text) + " must be a number > 0");
  }
  return *value;
}

// The annulus edges from --annuli DR:N (default 0.1 mean free paths, 100 annuli), in the output's unit.
std::vector<double> annulus_edges(std::optional<std::string_view> text, double default_width) {
  if (!text) {
    std::vector<double> edges;
    for (int i = 0; i <= 100; ++i) edges.push_back(text::decimal_multiple(default_width, i));
    return edges;
  }
  const std::vector<std::string_view> parts = split_list(*text, ':');
  if (parts.size() != 2) throw UsageError("annuli = " + text::quoted(*text) + " must be DR:N, as in --annuli 0.05:40");
  const double width = positive_number("annuli's width DR", parts[0]);
  const std::optional<double> count = text::parse_number(parts[1]);
  if (!count || *count != std::floor(*count) || *count < 1 || *count > kMaxAnnuli) {
    throw UsageError("annuli = " + text::quoted(*text) + ": the count N must be a whole number in [1, " +
                     std::to_string(kMaxAnnuli) + "]");
  }
  std::vector<double> edges;
  for (int i = 0; i <= static_cast<int>(*count); ++i) edges.push_back(text::decimal_multiple(width, i));
  return edges;
}

std::vector<double> radius_list(std::string_view text) {
  std::vector<double> radii;
  for (const std::string_view item : split_list(text, ',')) radii.push_back(positive_number("radii", item));
  return radii;
}

}  // namespace

std::string profile_usage() {
  return "Usage: skinlayer profile [material flags] [--incidence normal|diffuse] [--annuli DR:N | --radii LIST]\n"
         "\n"
         "Where light entering at a point leaves the layer: of a pencil beam at normal incidence (or diffuse light,\n"
         "--incidence diffuse), the scattered light leaving the top\n"
         "(reflectance) and the bottom (transmittance, the direct beam left out) per unit area and unit incident\n"
         "power. Writes, per annulus about the entry point (the mean over it),\n"
         "  r_inner_U,r_outer_U,reflectance,transmittance\n"
         "or, with --radii, per radius (the value there; the profile is infinite at r = 0)\n"
         "  r_U,reflectance,transmittance\n"
         "in 1/U^2, where U is mm when the layer has its extinction (--mu-t, 1/mm) and mfp, its mean free path,\n"
         "when it has none. An RGB albedo writes reflectance_r, _g, _b and transmittance_r, _g, _b.\n"
         "Each layer needs its mu_t when there are several. Below: an index-matched bottom (--bottom matched), a\n"
         "half-space (--T 0, or a last layer's tau=inf), a rough bottom interface (--bottom air) or a Lambertian\n"
         "base, the last two under a rough top or in diffuse light. Interfaces between layers are taken under a\n"
         "rough top (or diffuse light) over a half-space. A skin is such a stack: its columns are linear sRGB\n"
         "from 31 wavelengths (400-700 nm), or one wavelength's with --wavelength NM. Under a rough top the\n"
         "reflectance leaves out the interface's own reflection, which leaves at the entry point. Light that\n"
         "crosses unscattered or is scattered once, singular at the beam, is exact; the rest comes from the\n"
         "discrete ordinates in the lateral frequency (docs/model.md section 21): about 0.2 s per channel for one\n"
         "layer, 0.5 s per wavelength for a skin, on both cores. A finite layer lit through a rough top or\n"
         "diffusely has its transmittance computed on 24 nodes, about 2 s per channel.\n"
         "\n"
         "  --incidence normal|diffuse\n"
         "      a pencil beam along the normal (the default), or light of the same power arriving at the entry\n"
         "      point diffusely, from every direction of the hemisphere (radiance 1/pi per unit power).\n"
         "  --annuli DR:N\n"
         "      N annuli of width DR (in U) from the entry point; default 0.1 mean free paths, 100 annuli.\n"
         "  --radii LIST\n"
         "      comma-separated radii > 0 (in U) at which to give the profile, instead of annuli.\n" +
         rgb_albedo_usage() + "\n" + skin_flags_usage() + "\n" + material_flags_usage() +
         "\n"
         "Examples:\n"
         "  skinlayer profile --eta 1 --bottom matched --T 0 --albedo 0.99 --g 0.8 --mu-t 10 --annuli 0.05:60\n"
         "  skinlayer profile --eta 1 --bottom matched --tau 2 --albedo 0.9,0.8,0.6 --radii 0.1,0.5,1,2\n"
         "  skinlayer profile --eta 1.4 --sigma 0.3 --T 0 --albedo 0.95 --g 0.8 --mu-t 20 --annuli 0.02:100\n"
         "  skinlayer profile --skin melanin=0.05 --wavelength 650 --radii 0.1,0.5,1,2\n";
}

int run_profile_command(std::span<const std::string_view> arguments, std::ostream& out, std::ostream& progress) {
  const ParsedFlags flags = ParsedFlags::parse(
      arguments, material_flags_and({kIncidenceFlag, kAnnuliFlag, kRadiiFlag, kSkinFlag, kWavelengthFlag}),
      "skinlayer profile");
  const std::string_view incidence_name = flags.value(kIncidenceFlag).value_or("normal");
  if (incidence_name != "normal" && incidence_name != "diffuse") {
    throw UsageError("incidence = " + text::quoted(incidence_name) + " is not one of normal, diffuse");
  }
  const Incidence incidence = incidence_name == "diffuse" ? Incidence::Diffuse : Incidence::Normal;
  if (flags.has(kAnnuliFlag) && flags.has(kRadiiFlag)) {
    throw UsageError("flags --annuli and --radii both choose where the profile is given; give only one");
  }
  MaterialDocument document = material_document_from_flags(flags, AlbedoFlag::GreyOrRgb);
  if (const std::optional<double> wavelength = wavelength_from_flags(flags)) {
    document = document_at_wavelength(document, *wavelength);
  }
  const bool at_radii = flags.has(kRadiiFlag);
  // The default annuli are 0.1 mean free paths wide, in the output's unit.
  const double mu_t = document.skin ? 1.0 : document.layer.extinction.value_or(1.0);
  const std::vector<double> positions =
      at_radii ? radius_list(*flags.value(kRadiiFlag)) : annulus_edges(flags.value(kAnnuliFlag), 0.1 / mu_t);
  ProfileRequest request;
  request.incidence = incidence;
  request.options.parallel_for = parallel_for_threads;
  if (document.skin) {  // a skin's 31 wavelengths take about 18 s: a line every tenth of them
    request.progress = [&](int done, int total) {
      if (done * 10 / total != (done - 1) * 10 / total) {
        progress << "profile: " << done << " of " << total << " wavelengths\n" << std::flush;
      }
    };
  } else {  // an RGB albedo's distinct channels take 0.2-2 s each (a finite layer's transmittance: 24 nodes)
    request.progress = [&](int done, int total) {
      if (total > 1) progress << "profile: " << done << " of " << total << " distinct channels\n" << std::flush;
    };
  }
  const DocumentProfile profile = at_radii ? document_profile_at_radii(document, positions, request)
                                           : document_profile_in_annuli(document, positions, request);
  const std::string& unit = profile.unit;
  const std::size_t channels = profile.reflectance.size();

  const std::vector<std::string> inputs =
      at_radii ? std::vector<std::string>{"r_" + unit} : std::vector<std::string>{"r_inner_" + unit, "r_outer_" + unit};
  std::vector<std::string> columns;
  for (const std::string quantity : {"reflectance", "transmittance"}) {
    const std::vector<std::string> names = channels == 1 ? std::vector{quantity} : channel_columns(quantity);
    columns.insert(columns.end(), names.begin(), names.end());
  }
  NumericTable table(inputs, columns);
  const std::size_t rows = at_radii ? positions.size() : positions.size() - 1;
  for (std::size_t i = 0; i < rows; ++i) {
    std::vector<double> row = {positions[i]};
    if (!at_radii) row.push_back(positions[i + 1]);
    for (const std::vector<double>& channel : profile.reflectance) row.push_back(channel[i]);
    for (const std::vector<double>& channel : profile.transmittance) row.push_back(channel[i]);
    table.add_row(row);
  }
  table.require_finite();
  table.write_csv(out);
  return kExitSuccess;
}

}  // namespace skinlayer::cli
