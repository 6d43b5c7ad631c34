// The layer's parameters: one value type, one table of descriptors, one validation.
//
// The descriptor table (parameter_table()) is the single source of every parameter's name, symbol, range, default
// and meaning. The command line, the UI, reset-to-default and the range errors all read it.
#pragma once

#include <cmath>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/interfaces/microfacet_model.h"

namespace skinlayer {

// Thrown for a parameter outside its valid range (or not a number). The message names the parameter and its range.
class ParameterError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

enum class BottomKind {
  Air,      // a rough dielectric interface to a medium of lower index below (by default air, like the top)
  Matched,  // an index-matched half-space below: no interface at all
  Lambert,  // a diffuse (Lambertian) base of albedo A directly under the layer ("bone")
};

struct Bottom {
  BottomKind kind = BottomKind::Air;
  std::optional<double> sigma;  // Air only: Beckmann RMS slope; unset = the top's sigma
  std::optional<double> eta;    // Air only: n_layer / n_below; unset = the top's eta (air below)
  double lambert_albedo = 0.0;  // Lambert only: A in [0, 1]
  bool operator==(const Bottom&) const = default;
};

// A rough dielectric interface between two stacked layers (Beckmann, as the top): eta = n_this / n_above, the
// index of the layer under the interface relative to the one over it; eta = 1 is no interface.
struct LayerInterface {
  double sigma = 0.5;  // Beckmann RMS slope
  double eta = 1.0;    // n_this / n_above
  bool operator==(const LayerInterface&) const = default;
};

// A homogeneous slab under the first one (Material's own tau, albedo and g are the first layer's).
struct StackedLayer {
  double tau = 1.0;                         // optical depth; +infinity (semi-infinite) only for the last layer
  double albedo = 1.0;                      // single-scattering albedo Omega
  double g = 0.0;                           // Henyey-Greenstein asymmetry
  std::optional<LayerInterface> interface;  // a rough interface above this layer; unset = same index, none
  std::optional<double> extinction = std::nullopt;  // mu_t = mu_a + mu_s in 1/mm; unset = no physical length
  bool operator==(const StackedLayer&) const = default;
};

struct Material {
  double sigma = 0.5;      // top interface Beckmann RMS slope (Beckmann alpha), dimensionless
  double eta = 1.4;        // top interface relative index n_layer / n_air
  double tau = 1.6094379124341003;  // optical depth tau_b = -ln T; +infinity = semi-infinite (T = 0). Default T = 0.2
  double albedo = 1.0;     // single-scattering albedo Omega
  double g = 0.8;          // Henyey-Greenstein asymmetry
  // The first layer's extinction coefficient mu_t = mu_a + mu_s in 1/mm, which gives the material a length: the
  // layer's thickness is tau / mu_t mm and its mean free path 1 / mu_t mm. Unset = lengths in mean free paths only.
  std::optional<double> extinction = std::nullopt;
  Bottom bottom;
  std::optional<int> ordinates;  // discrete ordinates per hemisphere; unset = automatic
  // Layers 2..n of a stack, top to bottom; empty = the single layer above. The bottom is under the last one.
  std::vector<StackedLayer> below;
  // What every rough interface of the material keeps of the light that meets its microsurface
  // (core/interfaces/microfacet_model.h). Multiple conserves energy; Single is Stam 2001's model.
  MicrofacetModel microfacet = MicrofacetModel::Multiple;

  double transparency() const { return std::exp(-tau); }  // T = exp(-tau_b), of the first layer
  double bottom_sigma() const { return bottom.sigma.value_or(sigma); }
  // n_last / n_below; unset = air below the last layer (the top's eta times every internal interface's).
  double bottom_eta() const { return bottom.eta.value_or(eta * internal_index_ratio()); }

  int layer_count() const { return 1 + static_cast<int>(below.size()); }
  // The optical depth of the whole stack (+infinity when its last layer is semi-infinite).
  double total_tau() const;
  // True when some interface between layers refracts (eta != 1).
  bool has_internal_interfaces() const;
  // n_last / n_first: the product of the internal interfaces' eta.
  double internal_index_ratio() const;

  bool operator==(const Material&) const = default;
};

// True when a and b differ in nothing but their layers' single-scattering albedos (the channels of one material).
bool differ_only_in_albedos(const Material& a, const Material& b);

// The layers of a stack as single-layer values (tau, albedo, g of layer i, and its interface above; the first has
// none), top to bottom.
std::vector<StackedLayer> stack_layers(const Material& material);

// A layer's thickness in mm, tau / mu_t: +infinity for a semi-infinite layer, unset without an extinction.
std::optional<double> layer_thickness_mm(const StackedLayer& layer);
// The length of one mean free path of the first layer, 1 / mu_t in mm; unset without its extinction. Lateral
// distances (profiles) are measured in this unit when a material has no physical length.
std::optional<double> mean_free_path_mm(const Material& material);

// T = exp(-tau_b); T = 0 gives tau_b = +infinity.
double optical_depth_from_transparency(double transparency);

// One row of the parameter table.
struct ParameterInfo {
  std::string_view flag;         // command-line flag without the dashes, e.g. "sigma"
  std::string_view symbol;       // e.g. "σ"
  std::string_view description;  // one line of meaning
  double min;
  double max;  // may be +infinity
  double default_value;
};

// Every numeric parameter, in display order: sigma, eta, T, tau, albedo, g, mu-t, bottom-sigma, bottom-eta,
// lambert albedo, ordinates.
std::span<const ParameterInfo> parameter_table();
const ParameterInfo& parameter_info(std::string_view flag);
// The relative index n_this / n_above of an interface between stacked layers (LayerInterface::eta): either side
// may be the denser one. Not a row of parameter_table() (it is per layer).
const ParameterInfo& interface_eta_info();

// "[<min>, <max>]", as the range errors and the help print it ("%.10g"; "inf" for an unbounded maximum).
std::string range_text(const ParameterInfo& info);

// Throws ParameterError unless value is a number in [info.min, info.max]. The message reads
// "<flag> = <value> is out of range; valid range is [<min>, <max>] (<description>)".
void check_parameter(const ParameterInfo& info, double value);
// The same naming the parameter as the caller spells it (a --layer key "mu_t" for the row "mu-t").
void check_parameter(const ParameterInfo& info, double value, std::string_view name);

// Validates every field of the material against the table. Throws ParameterError naming the first bad field; a
// stacked layer's message starts "layer <i>: " (1-based, top to bottom), its interface's keys are "sigma" and "eta".
// Only the last layer of a stack may be semi-infinite.
void validate(const Material& material);

// Parses a bottom specification: "air", "matched" or "lambert:A". Throws ParameterError on anything else.
Bottom parse_bottom(std::string_view text);
std::string format_bottom(const Bottom& bottom);

}  // namespace skinlayer
