// A profile against MCML's annuli (tests/reference/README.md), as the profile tests judge it: where the profile
// exceeds 1e-3 of its peak (and from the radius `from` on), within 2% plus three times MCML's noise,
// 1/sqrt(photons P) relative for an annulus of power P.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>

#include "core/conventions.h"

namespace skinlayer::test {

// profile and mcml per unit area in one unit, edges (one more) in its length; `each` prints every annulus. Returns
// the worst judged annulus as a fraction of its bound, which it prints too.
inline double expect_within_mcml_noise(const std::string& label, std::span<const double> profile,
                                       std::span<const double> mcml, std::span<const double> edges, double photons,
                                       bool each = false, double from = 0.0) {
  double peak = 0.0, worst = 0.0;
  for (const double v : profile) peak = std::max(peak, v);
  for (std::size_t i = 0; i < mcml.size(); ++i) {
    const double r0 = edges[i], r1 = edges[i + 1];
    const double noise = 1.0 / std::sqrt(photons * mcml[i] * kPi * (r1 * r1 - r0 * r0));
    const double relative = profile[i] / mcml[i] - 1.0;
    if (each) {
      std::printf("  %s [%.3g, %.3g)  profile %.4e  MCML %.4e  (%+.2f%%, noise %.1f%%)\n", label.c_str(), r0, r1,
                  profile[i], mcml[i], 100.0 * relative, 100.0 * noise);
    }
    if (profile[i] < 1e-3 * peak || r0 < from) continue;
    worst = std::max(worst, std::abs(relative) / (0.02 + 3.0 * noise));
    EXPECT_LT(std::abs(relative), 0.02 + 3.0 * noise)
        << label << " annulus " << r0 << "-" << r1 << ": profile " << profile[i] << ", MCML " << mcml[i];
  }
  std::printf("  %s: %zu annuli, worst at %.0f%% of the tolerance\n", label.c_str(), mcml.size(), 100.0 * worst);
  return worst;
}

}  // namespace skinlayer::test
