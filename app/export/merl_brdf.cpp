#include "app/export/merl_brdf.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstring>
#include <vector>

#include "core/conventions.h"

namespace skinlayer {
namespace {

// Bin centres in index space. theta_h is spaced by the square root: index = 90 sqrt(theta_h / (pi/2)), so the centre
// of bin i lies at theta_h = (pi/2) ((i + 1/2) / 90)^2; theta_d and phi_d are uniform on [0, pi/2) and [0, pi).
double theta_h_centre(int i) {
  const double x = (i + 0.5) / kMerlThetaH;
  return 0.5 * kPi * x * x;
}
double theta_d_centre(int i) { return 0.5 * kPi * (i + 0.5) / kMerlThetaD; }
double phi_d_centre(int i) { return kPi * (i + 0.5) / kMerlPhiD; }

}  // namespace

MerlBinDirections merl_bin_directions(int theta_h, int theta_d, int phi_d) {
  const double th = theta_h_centre(theta_h), td = theta_d_centre(theta_d), pd = phi_d_centre(phi_d);
  const Vec3 d(std::sin(td) * std::cos(pd), std::sin(td) * std::sin(pd), std::cos(td));
  // omega_i = R_y(theta_h) d (phi_h = 0); h = R_y(theta_h) z.
  const Vec3 incident(std::cos(th) * d.x() + std::sin(th) * d.z(), d.y(), -std::sin(th) * d.x() + std::cos(th) * d.z());
  const Vec3 h(std::sin(th), 0.0, std::cos(th));
  const Vec3 outgoing = 2.0 * incident.dot(h) * h - incident;
  return {incident, outgoing};
}

std::string encode_merl(const RgbBrdf& brdf, const std::function<void(int, int)>& progress,
                        const std::function<void(int, const std::function<void(int)>&)>& parallel_for) {
  std::vector<double> values(3 * kMerlBins);
  std::atomic<int> rows_done{0};
  const auto row = [&](int theta_h) {
    for (int theta_d = 0; theta_d < kMerlThetaD; ++theta_d) {
      for (int phi_d = 0; phi_d < kMerlPhiD; ++phi_d) {
        const std::size_t index = static_cast<std::size_t>(phi_d) + std::size_t{kMerlPhiD} * theta_d +
                                  std::size_t{kMerlPhiD} * kMerlThetaD * theta_h;
        const MerlBinDirections bin = merl_bin_directions(theta_h, theta_d, phi_d);
        const std::array<double, 3> f =
            bin.above_horizon() ? brdf(bin.incident, bin.outgoing) : std::array<double, 3>{};
        for (std::size_t c = 0; c < 3; ++c) {
          values[c * kMerlBins + index] = bin.above_horizon() ? f[c] * kMerlScale[c] : kMerlBelowHorizon;
        }
      }
    }
    ++rows_done;
  };
  if (parallel_for) {
    // In blocks, so that progress can be reported between them from the calling thread.
    constexpr int kBlock = 10;
    for (int start = 0; start < kMerlThetaH; start += kBlock) {
      parallel_for(std::min(kBlock, kMerlThetaH - start), [&](int k) { row(start + k); });
      if (progress) progress(rows_done.load(), kMerlThetaH);
    }
  } else {
    for (int theta_h = 0; theta_h < kMerlThetaH; ++theta_h) {
      row(theta_h);
      if (progress && (theta_h + 1) % 10 == 0) progress(theta_h + 1, kMerlThetaH);
    }
  }
  std::string bytes(kMerlBytes, '\0');
  const std::int32_t dims[3] = {kMerlThetaH, kMerlThetaD, kMerlPhiD};
  static_assert(std::endian::native == std::endian::little, "the MERL file is little-endian");
  std::memcpy(bytes.data(), dims, sizeof dims);
  std::memcpy(bytes.data() + sizeof dims, values.data(), values.size() * sizeof(double));
  return bytes;
}

}  // namespace skinlayer
