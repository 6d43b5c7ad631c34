#include "app/cli/layer_flag.h"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "app/cli/errors.h"
#include "app/cli/flag_parser.h"
#include "app/material/exact_transparency.h"
#include "app/text/numbers.h"
#include "app/text/quoted.h"

namespace skinlayer::cli {
namespace {

constexpr std::array<std::string_view, 7> kKeys = {"T", "tau", "albedo", "g", "mu_t", "sigma", "eta"};
constexpr std::string_view kExample = "as in --layer T=0.5,albedo=0.9,g=0.8";

std::string prefix(int place) { return "layer " + std::to_string(place) + ": "; }

double checked(const ParameterInfo& info, std::string_view key, std::string_view text, int place) {
  const std::optional<double> value = text::parse_number(text);
  if (!value) {
    throw UsageError(prefix(place) + std::string(key) + " = " + text::quoted(text) + " " +
                     text::number_rejection(text) + "; valid range is " + range_text(info) + " (" +
                     std::string(info.description) + ")");
  }
  try {
    check_parameter(info, *value, key);  // named as the layer spells it ("mu_t" for the row "mu-t")
  } catch (const ParameterError& error) {
    throw ParameterError(prefix(place) + error.what());
  }
  return *value;
}

}  // namespace

LayerSpec parse_layer_spec(std::string_view text, int place, bool rgb_albedo) {
  std::vector<std::pair<std::string_view, std::string_view>> pairs;
  for (const std::string_view item : split_list(text, ',')) {
    const std::size_t equals = item.find('=');
    if (item.empty() || equals == std::string_view::npos) {
      throw UsageError(prefix(place) + text::quoted(item) +
                       " is not KEY=VALUE; keys are T or tau, albedo, g, mu_t, sigma, eta, " + std::string(kExample));
    }
    const std::string_view key = item.substr(0, equals);
    if (std::find(kKeys.begin(), kKeys.end(), key) == kKeys.end()) {
      throw UsageError(prefix(place) + "unknown key " + text::quoted(key) +
                       "; keys are T or tau, albedo, g, mu_t, sigma, eta");
    }
    if (std::any_of(pairs.begin(), pairs.end(), [&](const auto& p) { return p.first == key; })) {
      throw UsageError(prefix(place) + "key " + std::string(key) + " is given more than once");
    }
    pairs.emplace_back(key, item.substr(equals + 1));
  }
  const auto find = [&](std::string_view key) -> std::optional<std::string_view> {
    for (const auto& [k, v] : pairs) {
      if (k == key) return v;
    }
    return std::nullopt;
  };

  LayerSpec spec;
  const auto t = find("T"), tau = find("tau");
  if (t && tau) throw UsageError(prefix(place) + "give T or tau, not both (T = exp(-tau))");
  if (!t && !tau) {
    throw UsageError(prefix(place) + "give its depth as T (transparency, [0, 1]) or tau (optical depth), " +
                     std::string(kExample));
  }
  spec.tau = t ? optical_depth_from_transparency(checked(parameter_info("T"), "T", *t, place))
               : checked(parameter_info("tau"), "tau", *tau, place);
  const ParameterInfo& albedo_info = parameter_info("albedo");
  spec.albedo.fill(albedo_info.default_value);
  if (const auto albedo = find("albedo")) {
    const std::vector<std::string_view> parts = split_list(*albedo, ':');
    if (parts.size() == 3 && !rgb_albedo) {
      throw UsageError(prefix(place) + "albedo = " + text::quoted(*albedo) +
                       " is RGB and this command solves one channel; give one number in [0, 1]");
    }
    if (parts.size() != 1 && parts.size() != 3) {
      throw UsageError(prefix(place) + "albedo = " + text::quoted(*albedo) + " must be one number" +
                       (rgb_albedo ? " or three (r:g:b)" : "") + ", each in [0, 1]");
    }
    for (std::size_t c = 0; c < 3; ++c) {
      spec.albedo[c] = checked(albedo_info, "albedo", parts[parts.size() == 1 ? 0 : c], place);
    }
  }
  spec.g = parameter_info("g").default_value;
  if (const auto g = find("g")) spec.g = checked(parameter_info("g"), "g", *g, place);
  if (const auto mu_t = find("mu_t")) spec.extinction = checked(parameter_info("mu-t"), "mu_t", *mu_t, place);
  const auto sigma = find("sigma"), eta = find("eta");
  if ((sigma || eta) && place == 1) {
    throw UsageError(
        prefix(place) +
        "sigma and eta describe an interface above a layer; the first layer's is the top (--sigma, --eta)");
  }
  if (sigma.has_value() != eta.has_value()) {
    throw UsageError(prefix(place) + "give both sigma and eta of the interface above the layer, or neither");
  }
  if (sigma) {
    spec.interface = LayerInterface{checked(parameter_info("sigma"), "sigma", *sigma, place),
                                    checked(interface_eta_info(), "eta", *eta, place)};
  }
  return spec;
}

}  // namespace skinlayer::cli
