#include "app/cli/skin_flag.h"

#include <algorithm>
#include <vector>

#include "app/cli/errors.h"
#include "app/text/numbers.h"
#include "app/text/quoted.h"
#include "core/skin/skin_optics.h"

namespace skinlayer::cli {
namespace {

std::string key_list() {
  std::string keys;
  for (const ParameterInfo& info : skin_parameter_table()) {
    if (!keys.empty()) keys += ", ";
    keys.append(info.flag);
  }
  return keys;
}

constexpr std::string_view kExample = "as in --skin melanin=0.05,blood=0.02";

}  // namespace

SkinParameters parse_skin_spec(std::string_view text, const SkinParameters& base) {
  SkinParameters skin = base;
  std::vector<std::string_view> seen;
  for (const std::string_view item : split_list(text, ',')) {
    const std::size_t equals = item.find('=');
    if (item.empty() || equals == std::string_view::npos) {
      throw UsageError("skin: " + text::quoted(item) + " is not KEY=VALUE; keys are " + key_list() + ", " +
                       std::string(kExample));
    }
    const std::string_view key = item.substr(0, equals);
    const std::string_view value_text = item.substr(equals + 1);
    const auto& table = skin_parameter_table();
    const auto info = std::find_if(table.begin(), table.end(), [&](const ParameterInfo& i) { return i.flag == key; });
    if (info == table.end()) throw UsageError("skin: unknown key " + text::quoted(key) + "; keys are " + key_list());
    if (std::find(seen.begin(), seen.end(), key) != seen.end()) {
      throw UsageError("skin: key " + std::string(key) + " is given more than once");
    }
    seen.push_back(key);
    const std::optional<double> value = text::parse_number(value_text);
    if (!value) {
      throw UsageError("skin: " + std::string(key) + " = " + text::quoted(value_text) + " " +
                       text::number_rejection(value_text) + "; valid range is " + range_text(*info) + " (" +
                       std::string(info->description) + ")");
    }
    try {
      check_parameter(*info, *value);
    } catch (const ParameterError& error) {
      throw ParameterError(std::string("skin: ") + error.what());
    }
    skin_parameter(skin, key) = *value;
  }
  return skin;
}

std::optional<double> wavelength_from_flags(const ParsedFlags& flags) {
  const std::optional<std::string_view> text = flags.value(kWavelengthFlag);
  if (!text) return std::nullopt;
  const std::optional<double> value = text::parse_number(*text);
  if (!value) {
    throw UsageError("wavelength = " + text::quoted(*text) + " " + text::number_rejection(*text) +
                     "; valid range is [360, 830] (nm)");
  }
  if (!(*value >= 360.0 && *value <= 830.0)) {
    throw ParameterError("wavelength = " + text::format_number(*value) +
                         " is out of range; valid range is [360, 830] (nm)");
  }
  return value;
}

MaterialDocument document_at_wavelength(const MaterialDocument& document, double wavelength_nm) {
  if (document.skin) return skin_document_at_wavelength(document, wavelength_nm);
  if (!document.grey()) {
    throw UsageError(
        "flag --wavelength picks one wavelength of a spectrum, and an RGB material has none; give"
        " --skin, or --albedo A");
  }
  return document;
}

std::string skin_flags_usage(bool with_wavelength) {
  std::string text =
      "  --skin KEY=VALUE[,KEY=VALUE...]\n"
      "      a two-layer skin from its chromophores: an epidermis over a semi-infinite dermis under the top\n"
      "      interface (--sigma, --eta), solved per wavelength over 400-700 nm in 10 nm steps. Keys:\n";
  for (const ParameterInfo& info : skin_parameter_table()) {
    text += "        " + std::string(info.flag) + std::string(12 - info.flag.size(), ' ') +
            std::string(info.description) + "; range " + range_text(info) + ", default " +
            text::format_shortest(info.default_value) + "\n";
  }
  if (!with_wavelength) return text;
  text +=
      "  --wavelength NM\n"
      "      that one wavelength's values (grey columns), in [360, 830] nm: a --skin's layers there, or a grey\n"
      "      material's (flat) spectrum.\n";
  return text;
}

}  // namespace skinlayer::cli
