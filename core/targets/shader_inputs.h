// The range checks of a target shader's inputs (docs/model.md §22): each failure is a ParameterError of one line
// naming the shader, the input and its range, "principled: roughness must be in [0, 1]", as every bad input is.
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>

namespace skinlayer {

class ShaderInputs {
 public:
  explicit ShaderInputs(std::string_view shader) : shader_(shader) {}

  void in_range(double value, double lo, double hi, std::string_view name) const;  // [lo, hi]
  void unit(double value, std::string_view name) const;                            // [0, 1]
  void unit(const Eigen::Array3d& color, std::string_view name) const;             // each channel in [0, 1]
  void non_negative(double value, std::string_view name) const;                    // finite, >= 0
  void positive(double value, std::string_view name) const;                        // finite, > 0
  // A part not built yet: its input must be 0.
  void not_built(double value, std::string_view name) const;

 private:
  [[noreturn]] void fail(std::string_view name, std::string_view range) const;
  std::string shader_;
};

}  // namespace skinlayer
