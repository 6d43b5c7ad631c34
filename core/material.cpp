#include "core/material.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdio>
#include <limits>

namespace skinlayer {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The single table of parameters. Ranges are the ones the solver is tested over.
constexpr std::array kParameters = {
    ParameterInfo{"sigma", "σ", "top interface Beckmann RMS slope", 0.05, 1.0, 0.5},
    ParameterInfo{"eta", "η", "top relative index n_layer/n_air (1 = no interface)", 1.0, 2.5, 1.4},
    ParameterInfo{"T", "T", "transparency exp(-tau); 0 = semi-infinite, 1 = no medium", 0.0, 1.0, 0.2},
    ParameterInfo{"tau", "τb", "optical depth; inf = semi-infinite", 0.0, kInf, 1.6094379124341003},
    ParameterInfo{"albedo", "Ω", "single-scattering albedo", 0.0, 1.0, 1.0},
    ParameterInfo{"g", "g", "Henyey-Greenstein asymmetry", -0.95, 0.95, 0.8},
    // From a mean free path of 1 km to one of 1 nm: every physical layer, with room for unit slips to show.
    ParameterInfo{"mu-t", "μt", "extinction coefficient mu_a + mu_s in 1/mm; the thickness is tau/mu_t mm", 1e-6, 1e6,
                  0.0},
    ParameterInfo{"bottom-sigma", "σ3", "bottom interface Beckmann RMS slope", 0.05, 1.0, 0.5},
    ParameterInfo{"bottom-eta", "η3", "bottom relative index n_layer/n_below (1 = no interface)", 1.0, 2.5, 1.4},
    ParameterInfo{"lambert", "A", "albedo of the Lambertian base", 0.0, 1.0, 0.5},
    ParameterInfo{"ordinates", "N", "discrete ordinates per hemisphere", 4.0, 256.0, 0.0},
};

// An internal interface's relative index n_this / n_above: either side may be denser.
constexpr ParameterInfo kInterfaceEta{"eta", "η", "interface relative index n_this/n_above (1 = no interface)",
                                      0.4,   2.5, 1.0};

std::string format_number(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.10g", value);
  return buffer;
}

}  // namespace

double optical_depth_from_transparency(double transparency) {
  check_parameter(parameter_info("T"), transparency);
  return transparency == 0.0 ? kInf : -std::log(transparency);
}

std::span<const ParameterInfo> parameter_table() { return kParameters; }

const ParameterInfo& parameter_info(std::string_view flag) {
  for (const ParameterInfo& info : kParameters) {
    if (info.flag == flag) return info;
  }
  throw std::logic_error("unknown parameter '" + std::string(flag) + "'");
}

const ParameterInfo& interface_eta_info() { return kInterfaceEta; }

std::string range_text(const ParameterInfo& info) {
  // Appended, not "[" + ...: GCC 12 reports a false -Wrestrict overlap for a literal prepended to a temporary.
  std::string text = "[";
  text.append(format_number(info.min)).append(", ").append(format_number(info.max)).append("]");
  return text;
}

void check_parameter(const ParameterInfo& info, double value) { check_parameter(info, value, info.flag); }

void check_parameter(const ParameterInfo& info, double value, std::string_view name) {
  if (!(value >= info.min && value <= info.max)) {  // false for NaN too
    throw ParameterError(std::string(name) + " = " + format_number(value) + " is out of range; valid range is " +
                         range_text(info) + " (" + std::string(info.description) + ")");
  }
}

void validate(const Material& material) {
  check_parameter(parameter_info("sigma"), material.sigma);
  check_parameter(parameter_info("eta"), material.eta);
  check_parameter(parameter_info("tau"), material.tau);
  check_parameter(parameter_info("albedo"), material.albedo);
  check_parameter(parameter_info("g"), material.g);
  if (material.bottom.sigma) check_parameter(parameter_info("bottom-sigma"), *material.bottom.sigma);
  if (material.bottom.eta) check_parameter(parameter_info("bottom-eta"), *material.bottom.eta);
  if (material.bottom.kind == BottomKind::Lambert) {
    check_parameter(parameter_info("lambert"), material.bottom.lambert_albedo);
  }
  if (material.ordinates) check_parameter(parameter_info("ordinates"), *material.ordinates);
  const auto in_layer = [](int index, const auto& check) {
    try {
      check();
    } catch (const ParameterError& e) {
      throw ParameterError("layer " + std::to_string(index) + ": " + e.what());
    }
  };
  const int layers = material.layer_count();
  if (material.extinction) {
    const auto check = [&] { check_parameter(parameter_info("mu-t"), *material.extinction); };
    layers > 1 ? in_layer(1, check) : check();
  }
  if (layers > 1 && std::isinf(material.tau)) {
    throw ParameterError("layer 1: tau = inf (T = 0) is allowed only for the last layer of a stack");
  }
  for (int i = 2; i <= layers; ++i) {
    const StackedLayer& layer = material.below[static_cast<std::size_t>(i - 2)];
    in_layer(i, [&] {
      check_parameter(parameter_info("tau"), layer.tau);
      check_parameter(parameter_info("albedo"), layer.albedo);
      check_parameter(parameter_info("g"), layer.g);
      if (layer.extinction) check_parameter(parameter_info("mu-t"), *layer.extinction);
      if (layer.interface) {
        check_parameter(parameter_info("sigma"), layer.interface->sigma);
        check_parameter(interface_eta_info(), layer.interface->eta);
      }
    });
    if (i < layers && std::isinf(layer.tau)) {
      throw ParameterError("layer " + std::to_string(i) +
                           ": tau = inf (T = 0) is allowed only for the last layer of a stack");
    }
  }
  // Air below the last layer by default: its relative index n_last / n_air must be a valid bottom-eta.
  if (layers > 1 && material.bottom.kind == BottomKind::Air && !material.bottom.eta) {
    const ParameterInfo& info = parameter_info("bottom-eta");
    const double eta = material.bottom_eta();
    if (!(eta >= info.min && eta <= info.max)) {
      throw ParameterError("bottom-eta = " + format_number(eta) +
                           " (n_last/n_air, air below: the top's eta times the interfaces') is out of range; valid "
                           "range is " +
                           range_text(info) + "; give --bottom-eta or change an interface's eta");
    }
  }
}

double Material::total_tau() const {
  double total = tau;
  for (const StackedLayer& layer : below) total += layer.tau;
  return total;
}

bool Material::has_internal_interfaces() const {
  return std::ranges::any_of(below, [](const StackedLayer& l) { return l.interface && l.interface->eta != 1.0; });
}

double Material::internal_index_ratio() const {
  double ratio = 1.0;
  for (const StackedLayer& layer : below) ratio *= layer.interface ? layer.interface->eta : 1.0;
  return ratio;
}

bool differ_only_in_albedos(const Material& a, const Material& b) {
  const auto without_albedos = [](Material m) {
    m.albedo = 0.0;
    for (StackedLayer& layer : m.below) layer.albedo = 0.0;
    return m;
  };
  return without_albedos(a) == without_albedos(b);
}

std::optional<double> layer_thickness_mm(const StackedLayer& layer) {
  if (!layer.extinction) return std::nullopt;
  return std::isinf(layer.tau) ? kInf : layer.tau / *layer.extinction;
}

std::optional<double> mean_free_path_mm(const Material& material) {
  if (!material.extinction) return std::nullopt;
  return 1.0 / *material.extinction;
}

std::vector<StackedLayer> stack_layers(const Material& material) {
  std::vector<StackedLayer> layers{{material.tau, material.albedo, material.g, std::nullopt, material.extinction}};
  layers.insert(layers.end(), material.below.begin(), material.below.end());
  return layers;
}

Bottom parse_bottom(std::string_view text) {
  Bottom bottom;
  if (text == "air") return bottom;
  if (text == "matched") {
    bottom.kind = BottomKind::Matched;
    return bottom;
  }
  constexpr std::string_view kLambert = "lambert:";
  if (text.starts_with(kLambert)) {
    const std::string_view number = text.substr(kLambert.size());
    double value = 0.0;
    const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (error != std::errc() || end != number.data() + number.size() || number.empty()) {
      throw ParameterError("bottom = '" + std::string(text) +
                           "': the Lambertian albedo must be a number in [0, 1], as in lambert:0.5");
    }
    check_parameter(parameter_info("lambert"), value);
    bottom.kind = BottomKind::Lambert;
    bottom.lambert_albedo = value;
    return bottom;
  }
  throw ParameterError("bottom = '" + std::string(text) + "' is not one of air, matched, lambert:A (A in [0, 1])");
}

std::string format_bottom(const Bottom& bottom) {
  switch (bottom.kind) {
    case BottomKind::Air: return "air";
    case BottomKind::Matched: return "matched";
    case BottomKind::Lambert: return "lambert:" + format_number(bottom.lambert_albedo);
  }
  return "air";
}

}  // namespace skinlayer
