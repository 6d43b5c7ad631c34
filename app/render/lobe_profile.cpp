#include "app/render/lobe_profile.h"

#include <algorithm>
#include <cmath>

#include "core/conventions.h"

namespace skinlayer {

std::vector<float> lobe_profile(const TableTextureData& tables, double theta_i) {
  const int size = tables.size;
  std::vector<float> profile(static_cast<std::size_t>(kLobeProfileRows) * size * 4, 0.0f);
  if (size < 2) return profile;
  // The row coordinate of theta_i on the grid map, in texels: x (size - 1) with x = asin(theta / (pi/2)) / (pi/2).
  const double x = std::asin(std::clamp(theta_i / (0.5 * kPi), 0.0, 1.0)) / (0.5 * kPi);
  const double position = x * (size - 1);
  const int row = std::clamp(static_cast<int>(std::floor(position)), 0, size - 2);
  const double fraction = std::clamp(position - row, 0.0, 1.0);
  const std::size_t plane = static_cast<std::size_t>(size) * size * 4;
  const auto add_modes = [&](const std::vector<float>& table, LobeProfileRow backward, LobeProfileRow forward) {
    float* back = &profile[static_cast<std::size_t>(backward) * size * 4];
    float* front = &profile[static_cast<std::size_t>(forward) * size * 4];
    for (int column = 0; column < size; ++column) {
      for (int channel = 0; channel < 3; ++channel) {
        double backward_sum = 0.0, forward_sum = 0.0;
        for (int m = 0; m < tables.modes; ++m) {
          const std::size_t texel = m * plane + (static_cast<std::size_t>(row) * size + column) * 4 + channel;
          const double value = (1.0 - fraction) * table[texel] + fraction * table[texel + size * 4];
          backward_sum += value;                         // cos(m 0) = 1
          forward_sum += (m % 2 == 0 ? value : -value);  // cos(m pi) = (-1)^m
        }
        back[column * 4 + channel] = static_cast<float>(backward_sum);
        front[column * 4 + channel] = static_cast<float>(forward_sum);
      }
    }
  };
  add_modes(tables.reflection, LobeProfileRow::ReflectionBackward, LobeProfileRow::ReflectionForward);
  add_modes(tables.transmission, LobeProfileRow::TransmissionBackward, LobeProfileRow::TransmissionForward);
  return profile;
}

}  // namespace skinlayer
