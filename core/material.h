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
};

struct Material {
  double sigma = 0.5;      // top interface Beckmann RMS slope (Beckmann alpha), dimensionless
  double eta = 1.4;        // top interface relative index n_layer / n_air
  double tau = 1.6094379124341003;  // optical depth tau_b = -ln T; +infinity = semi-infinite (T = 0). Default T = 0.2
  double albedo = 1.0;     // single-scattering albedo Omega
  double g = 0.8;          // Henyey-Greenstein asymmetry
  Bottom bottom;
  std::optional<int> ordinates;  // discrete ordinates per hemisphere; unset = automatic

  double transparency() const { return std::exp(-tau); }  // T = exp(-tau_b)
  double bottom_sigma() const { return bottom.sigma.value_or(sigma); }
  double bottom_eta() const { return bottom.eta.value_or(eta); }
};

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

// Every numeric parameter, in display order: sigma, eta, T, tau, albedo, g, bottom-sigma, bottom-eta,
// lambert albedo, ordinates.
std::span<const ParameterInfo> parameter_table();
const ParameterInfo& parameter_info(std::string_view flag);

// "[<min>, <max>]", as the range errors and the help print it ("%.10g"; "inf" for an unbounded maximum).
std::string range_text(const ParameterInfo& info);

// Throws ParameterError unless value is a number in [info.min, info.max]. The message reads
// "<flag> = <value> is out of range; valid range is [<min>, <max>] (<description>)".
void check_parameter(const ParameterInfo& info, double value);

// Validates every field of the material against the table. Throws ParameterError naming the first bad field.
void validate(const Material& material);

// Parses a bottom specification: "air", "matched" or "lambert:A". Throws ParameterError on anything else.
Bottom parse_bottom(std::string_view text);
std::string format_bottom(const Bottom& bottom);

}  // namespace skinlayer
