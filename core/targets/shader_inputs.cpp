#include "core/targets/shader_inputs.h"

#include <cmath>

#include "core/material.h"

namespace skinlayer {
namespace {

std::string shortest(double value) {
  std::string text = std::to_string(value);
  text.erase(text.find_last_not_of('0') + 1);
  if (text.back() == '.') text.pop_back();
  return text;
}

}  // namespace

void ShaderInputs::fail(std::string_view name, std::string_view range) const {
  throw ParameterError(shader_ + ": " + std::string(name) + " must be " + std::string(range));
}

void ShaderInputs::in_range(double value, double lo, double hi, std::string_view name) const {
  if (!(value >= lo && value <= hi)) fail(name, "in [" + shortest(lo) + ", " + shortest(hi) + "]");
}

void ShaderInputs::unit(double value, std::string_view name) const { in_range(value, 0.0, 1.0, name); }

void ShaderInputs::unit(const Eigen::Array3d& color, std::string_view name) const {
  for (int c = 0; c < 3; ++c) unit(color(c), name);
}

void ShaderInputs::non_negative(double value, std::string_view name) const {
  if (!(value >= 0.0) || !std::isfinite(value)) fail(name, ">= 0");
}

void ShaderInputs::positive(double value, std::string_view name) const {
  if (!(value > 0.0) || !std::isfinite(value)) fail(name, "> 0");
}

void ShaderInputs::not_built(double value, std::string_view name) const {
  if (value != 0.0) fail(name, "0: it is not built yet");
}

}  // namespace skinlayer
