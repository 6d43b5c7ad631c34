#include "core/skin/skin_parameters.h"

#include <array>
#include <stdexcept>
#include <string>

namespace skinlayer {
namespace {

const SkinParameters kDefaults;

const std::array<ParameterInfo, 6> kSkinTable{{
    {"melanin", "Cm", "epidermal melanin volume fraction", 0.0, 0.5, kDefaults.melanin},
    {"eumelanin", "βm", "eumelanin share of the melanin (the rest is pheomelanin)", 0.0, 1.0, kDefaults.eumelanin},
    {"blood", "Ch", "dermal blood volume fraction", 0.0, 0.2, kDefaults.blood},
    {"oxygenation", "S", "blood oxygen saturation", 0.0, 1.0, kDefaults.oxygenation},
    {"epidermis", "d", "epidermis thickness in mm", 0.01, 0.5, kDefaults.epidermis},
    {"scattering", "s", "scale on the reduced scattering of both layers", 0.25, 4.0, kDefaults.scattering},
}};

}  // namespace

std::span<const ParameterInfo> skin_parameter_table() { return kSkinTable; }

const ParameterInfo& skin_parameter_info(std::string_view key) {
  for (const ParameterInfo& info : kSkinTable)
    if (info.flag == key) return info;
  std::string keys;
  for (const ParameterInfo& info : kSkinTable) keys += (keys.empty() ? "" : ", ") + std::string(info.flag);
  throw std::invalid_argument("unknown skin parameter \"" + std::string(key) + "\"; the keys are " + keys);
}

double& skin_parameter(SkinParameters& p, std::string_view key) {
  const std::string_view flag = skin_parameter_info(key).flag;
  if (flag == "melanin") return p.melanin;
  if (flag == "eumelanin") return p.eumelanin;
  if (flag == "blood") return p.blood;
  if (flag == "oxygenation") return p.oxygenation;
  if (flag == "epidermis") return p.epidermis;
  return p.scattering;
}

double skin_parameter(const SkinParameters& p, std::string_view key) {
  SkinParameters copy = p;
  return skin_parameter(copy, key);
}

void validate(const SkinParameters& skin) {
  for (const ParameterInfo& info : kSkinTable) check_parameter(info, skin_parameter(skin, info.flag));
}

}  // namespace skinlayer
