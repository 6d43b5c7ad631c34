#include "app/cli/match_command.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "app/cli/errors.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/skin_flag.h"
#include "app/material/color_match.h"
#include "app/material/material_file.h"
#include "app/material/material_json.h"
#include "app/process/parallel_for.h"
#include "app/text/numbers.h"
#include "app/text/quoted.h"
#include "core/color/spectral_color.h"
#include "core/conventions.h"
#include "core/fit/skin_fit.h"

namespace skinlayer::cli {
namespace {

constexpr std::string_view kColorFlag = "color";
constexpr std::string_view kSpectrumFlag = "spectrum";
constexpr std::string_view kThetaFlag = "theta-i";
constexpr std::string_view kRangeFlag = "range";
constexpr std::string_view kLinearSwitch = "linear";

// "R,G,B" (each in [0, 1]) or "#RRGGBB".
std::array<double, 3> parse_color(std::string_view text) {
  std::array<double, 3> rgb{};
  if (!text.empty() && text.front() == '#') {
    const auto hex = [](char c) -> int {
      if (c >= '0' && c <= '9') return c - '0';
      if (c >= 'a' && c <= 'f') return c - 'a' + 10;
      if (c >= 'A' && c <= 'F') return c - 'A' + 10;
      return -1;
    };
    bool valid = text.size() == 7;
    for (std::size_t c = 0; valid && c < 3; ++c) {
      const int high = hex(text[1 + 2 * c]), low = hex(text[2 + 2 * c]);
      valid = high >= 0 && low >= 0;
      rgb[c] = (16 * high + low) / 255.0;
    }
    if (!valid) throw UsageError("color = " + text::quoted(text) + " is not #RRGGBB (six hexadecimal digits)");
    return rgb;
  }
  const std::vector<std::string_view> parts = split_list(text, ',');
  if (parts.size() != 3)
    throw UsageError("color = " + text::quoted(text) + " must be R,G,B (each in [0, 1]) or #RRGGBB");
  for (std::size_t c = 0; c < 3; ++c) {
    const std::optional<double> value = text::parse_number(parts[c]);
    if (!value) {
      throw UsageError("color = " + text::quoted(text) + ": " + text::quoted(parts[c]) + " " +
                       text::number_rejection(parts[c]));
    }
    if (!(*value >= 0.0 && *value <= 1.0)) {
      throw ParameterError("color = " + text::quoted(text) + ": " + text::format_number(*value) +
                           " is out of range; valid range is [0, 1] (each channel)");
    }
    rgb[c] = *value;
  }
  return rgb;
}

// "(0.7134, 0.6243, 0.5270)": sRGB-encoded, four decimals.
std::string color_text(const Eigen::Vector3d& linear) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.4f, %.4f, %.4f)", srgb_encode(std::max(0.0, linear(0))),
                srgb_encode(std::max(0.0, linear(1))), srgb_encode(std::max(0.0, linear(2))));
  return text;
}

std::string fixed_text(double value, int decimals) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

void write_document(const MaterialDocument& document, const ParsedFlags& flags, std::ostream& out) {
  if (const auto path = flags.value("output")) {
    if (path->empty()) throw UsageError("output needs a file name, as in -o matched.json");
    write_material_file(document, std::string(*path));
  } else {
    out << material_json_text(document);
  }
}

// CSV wavelength_nm,reflectance with an optional header and blank lines anywhere: the pairs, ascending (a file that
// descends throughout is read backwards). A reflectance above 1.5 gets the hint that the file may be in per cent.
void read_spectrum(const std::string& path, std::vector<double>& wavelengths, std::vector<double>& reflectance) {
  std::ifstream file(path);
  if (!file) throw UsageError("spectrum = " + text::quoted(path) + " cannot be read");
  std::string line;
  int number = 0;
  while (std::getline(file, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::vector<std::string_view> fields = split_list(line, ',');
    const auto where = [&] { return path + ":" + std::to_string(number) + ": "; };
    if (fields.size() != 2) throw InputError(where() + "expected wavelength_nm,reflectance");
    const std::optional<double> w = text::parse_number(fields[0]), r = text::parse_number(fields[1]);
    if (!w || !r) {
      if (number == 1) continue;  // a header
      throw InputError(where() + "expected two numbers, wavelength_nm,reflectance");
    }
    if (*r > 1.5 && *r <= 100.0) {
      throw InputError(where() + "reflectance " + text::format_number(*r) +
                       " is above 1.5: a fraction is expected; if the file is in per cent, divide it by 100");
    }
    if (!(*w > 0.0) || !(*r >= 0.0 && *r <= 1.5)) {
      throw InputError(where() + "wavelength must be positive and reflectance in [0, 1.5]");
    }
    if (wavelengths.size() >= 2 && (*w > wavelengths.back()) != (wavelengths.back() > wavelengths.front())) {
      throw InputError(where() + "wavelengths must ascend (or descend) throughout");
    }
    if (!wavelengths.empty() && *w == wavelengths.back()) throw InputError(where() + "a wavelength is repeated");
    wavelengths.push_back(*w);
    reflectance.push_back(*r);
  }
  if (wavelengths.size() >= 2 && wavelengths.back() < wavelengths.front()) {
    std::reverse(wavelengths.begin(), wavelengths.end());
    std::reverse(reflectance.begin(), reflectance.end());
  }
}

int match_spectrum(const ParsedFlags& flags, const MaterialDocument& document, std::ostream& out, std::ostream& err) {
  std::vector<double> wavelengths, reflectance;
  read_spectrum(std::string(*flags.value(kSpectrumFlag)), wavelengths, reflectance);
  const double theta = number_flag(flags, kThetaFlag, 8.0, 0.0, 90.0, " (degrees)");
  double from = 400.0, to = 700.0;
  if (const auto range = flags.value(kRangeFlag)) {
    const std::vector<std::string_view> ends = split_list(*range, ':');
    const std::optional<double> a = ends.size() == 2 ? text::parse_number(ends[0]) : std::nullopt;
    const std::optional<double> b = ends.size() == 2 ? text::parse_number(ends[1]) : std::nullopt;
    if (!a || !b || !(*a >= 360.0 && *b <= 830.0 && *a < *b)) {
      throw UsageError("range = " + text::quoted(*range) + " must be FROM:TO in nm, 360 <= FROM < TO <= 830");
    }
    from = *a;
    to = *b;
  }
  const SkinSpectrumFit fit = fit_skin_spectrum(wavelengths, reflectance, degrees_to_radians(theta), from, to,
                                                document.layer, parallel_for_threads);
  MaterialDocument matched = document;
  matched.skin = fit.skin;
  write_document(matched, flags, out);
  err << "skinlayer: match: RMS residual " << fixed_text(fit.rms, 4) << " in reflectance over "
      << fit.wavelengths_nm.size() << " wavelengths, " << text::format_number(fit.wavelengths_nm.front()) << "-"
      << text::format_number(fit.wavelengths_nm.back()) << " nm, at " << text::format_number(theta) << " degrees\n";
  return kExitSuccess;
}

int match_color(const ParsedFlags& flags, MaterialDocument document, std::ostream& out, std::ostream& err) {
  const std::array<double, 3> given = parse_color(*flags.value(kColorFlag));
  Eigen::Vector3d target;
  for (int c = 0; c < 3; ++c) {
    target(c) =
        flags.has(kLinearSwitch) ? given[static_cast<std::size_t>(c)] : srgb_decode(given[static_cast<std::size_t>(c)]);
  }
  const DocumentColorMatch match = match_document_color(std::move(document), target, parallel_for_threads);
  write_document(match.document, flags, out);
  if (!match.reachable) {
    err << "skinlayer: match: the colour " << color_text(target) << " is out of reach; the nearest reachable one is "
        << color_text(match.reached) << " (sRGB), CIEDE2000 " << fixed_text(match.delta_e, 2) << " away\n";
  }
  return kExitSuccess;
}

}  // namespace

std::string match_usage() {
  return "Usage: skinlayer match --color R,G,B|#RRGGBB [--linear] [material flags | --skin KEY=VALUE,...]\n"
         "                       [-o FILE.json]\n"
         "       skinlayer match --spectrum FILE.csv [--theta-i DEG] [--range FROM:TO] [material flags]\n"
         "                       [-o FILE.json]\n"
         "\n"
         "Pick the colour, get the parameters. --color is the colour of the sphere's centre under a white furnace:\n"
         "the reflectance at normal incidence, surface and subsurface, in linear sRGB (sRGB-encoded on the command\n"
         "line unless --linear; #RRGGBB is sRGB-encoded). With --skin (or a skin material), or with no material\n"
         "flags at all, match adjusts a skin's melanin, blood and scattering (the other skin keys stay as given);\n"
         "with other material flags, the top layer's albedo per channel.\n"
         "It writes the material file. A colour out of reach gives the nearest reachable one and one line on\n"
         "stderr naming the CIEDE2000 distance.\n"
         "--spectrum fits a measured directional-hemispherical reflectance spectrum, CSV wavelength_nm,reflectance\n"
         "on any grid, ascending or descending (a header line and blank lines are allowed; reflectance as a\n"
         "fraction, not per cent), with all six skin parameters, least squares at the measured\n"
         "wavelengths in the range (default 400:700 nm) at incidence --theta-i (default 8 degrees, the usual\n"
         "integrating-sphere geometry). It writes the material and one stderr line with the RMS residual.\n"
         "\n"
         "  -o, --output FILE    where to write the material file (atomically); default stdout\n" +
         skin_flags_usage(false) + "\n" + material_flags_usage() +
         "\n"
         "Example:\n"
         "  skinlayer match --color '#9d7a60' --skin melanin=0.02 -o matched.json\n"
         "  skinlayer match --color 0.6,0.4,0.3 --linear --preset wax\n"
         "  skinlayer match --spectrum forearm.csv --sigma 0.35 -o forearm.json\n";
}

int run_match_command(std::span<const std::string_view> arguments, std::ostream& out, std::ostream& err) {
  const std::vector<std::string_view> known =
      material_flags_and({kColorFlag, kSpectrumFlag, kThetaFlag, kRangeFlag, kSkinFlag, "output"});
  const std::string_view switches[] = {kLinearSwitch};
  const ParsedFlags flags = ParsedFlags::parse(arguments, known, "skinlayer match", switches);
  if (flags.has(kColorFlag) && flags.has(kSpectrumFlag)) {
    throw UsageError("match takes one of --color and --spectrum, not both: a colour or a measured spectrum");
  }
  if (!flags.has(kColorFlag) && !flags.has(kSpectrumFlag)) {
    throw UsageError("match needs one of --color R,G,B and --spectrum FILE.csv");
  }
  MaterialDocument document = material_document_from_flags(flags, AlbedoFlag::GreyOrRgb);
  // A colour with nothing else is a skin's: what the command is for, and what a grey layer of the paper's defaults
  // would only come near (skin-fair's own #C09F8B was 17.7 CIEDE2000 away from any albedo of that layer). Said on
  // stderr before the fit, with how to match a layer instead.
  const bool material_given =
      flags.has(kSkinFlag) || flags.has("material") || flags.has("preset") ||
      std::ranges::any_of(material_flag_names(), [&](std::string_view name) { return flags.has(name); });
  const bool skin_by_default = flags.has(kColorFlag) && !material_given;
  if (flags.has(kSpectrumFlag)) {
    if (flags.has(kLinearSwitch)) throw UsageError("--linear applies to --color, not --spectrum");
    if (!document.skin) document.skin = SkinParameters{};  // a spectrum fit is of the skin model
    return match_spectrum(flags, document, out, err);
  }
  if (flags.has(kThetaFlag) || flags.has(kRangeFlag)) {
    throw UsageError("--theta-i and --range apply to --spectrum; --color matches at normal incidence");
  }
  if (skin_by_default) {
    document.skin = SkinParameters{};
    (void)parse_color(*flags.value(kColorFlag));  // a malformed colour is the one line, before any notice
    err << "skinlayer: match: matching a skin (--skin with its defaults); give material flags (--preset, --layer, "
           "--T, ...) to match a layer's albedo instead\n";
  }
  return match_color(flags, document, out, err);
}

}  // namespace skinlayer::cli
