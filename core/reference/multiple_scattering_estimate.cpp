#include "core/reference/multiple_scattering_estimate.h"

#include <cmath>
#include <random>

#include "core/conventions.h"
#include "core/reference/microsurface_walk.h"

namespace skinlayer {

MultipleScatteringEstimate estimate_multiple_scattering(const RoughDielectric& interface, double theta_i,
                                                        bool from_above, std::span<const double> exit_thetas,
                                                        std::span<const double> exit_phis,
                                                        const MultipleScatteringEstimateOptions& options) {
  MultipleScatteringEstimate result;
  result.exit_thetas.assign(exit_thetas.begin(), exit_thetas.end());
  result.exit_phis.assign(exit_phis.begin(), exit_phis.end());
  const std::size_t thetas = exit_thetas.size(), phis = exit_phis.size();
  for (std::vector<double>& side : result.values) side.assign(thetas * phis, 0.0);
  if (interface.eta == 1.0) return result;  // no interface: the light passes, met once at most

  const double light_side = from_above ? 1.0 : -1.0;
  const Vec3 wi(std::sin(theta_i), 0.0, light_side * std::cos(theta_i));
  std::vector<double> lambda(thetas), cosine(thetas);
  std::vector<Vec3> exits(thetas * phis);  // on the light's side, world frame, at +phi
  for (std::size_t k = 0; k < thetas; ++k) {
    cosine[k] = std::cos(exit_thetas[k]);
    const double sine = std::sin(exit_thetas[k]);
    lambda[k] = beckmann_lambda(Vec3(sine, 0.0, cosine[k]), interface.sigma);
    for (std::size_t j = 0; j < phis; ++j) {
      exits[k * phis + j] = Vec3(sine * std::cos(exit_phis[j]), sine * std::sin(exit_phis[j]), light_side * cosine[k]);
    }
  }
  std::vector<double> sums[2];
  for (std::vector<double>& side : sums) side.assign(thetas * phis, 0.0);
  bool met_again = false;
  const MeetingVisitor visit = [&](const MicrosurfaceMeeting& meeting) {
    if (meeting.order < 2) return;
    met_again = true;
    const double meeting_side = meeting.above ? 1.0 : -1.0;
    const MicrosurfaceScatterDensity scatter(interface, meeting.above, meeting.toward_source);
    for (int side = 0; side < 2; ++side) {
      // The exit's z in the meeting medium's frame: + leaves on the meeting's side, - beyond it.
      const double z_sign = meeting_side * light_side * (side == 0 ? 1.0 : -1.0);
      const double height = z_sign > 0.0 ? meeting.height_cdf : 1.0 - meeting.height_cdf;
      for (std::size_t k = 0; k < thetas; ++k) {
        const double unmet = height > 0.0 ? std::pow(height, lambda[k]) : 0.0;
        if (unmet <= 0.0) continue;
        for (std::size_t j = 0; j < phis; ++j) {
          const Vec3& back = exits[k * phis + j];
          const double x = meeting_side * back.x(), y = meeting_side * back.y(), z = z_sign * cosine[k];
          const double density = scatter(Vec3(x, y, z)) + scatter(Vec3(x, -y, z));  // +phi and -phi
          sums[side][k * phis + j] += 0.5 * density * unmet;
        }
      }
    }
  };

  const MicrosurfaceWalk walk(interface);
  std::mt19937_64 random(options.seed);
  long walks = 0;
  while (walks < options.max_walks &&
         (walks < options.min_walks || result.walks_with_meetings < options.walks_with_meetings)) {
    met_again = false;
    walk.walk(wi, random, visit);
    ++walks;
    if (met_again) ++result.walks_with_meetings;
  }
  result.walks = walks;
  for (int side = 0; side < 2; ++side) {
    for (std::size_t k = 0; k < thetas; ++k) {
      for (std::size_t j = 0; j < phis; ++j) {
        result.values[side][k * phis + j] = sums[side][k * phis + j] / (static_cast<double>(walks) * cosine[k]);
      }
    }
  }
  return result;
}

}  // namespace skinlayer
