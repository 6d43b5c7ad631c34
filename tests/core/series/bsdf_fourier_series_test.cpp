// The whole BSDF as Fourier series (core/series/bsdf_fourier_series.h) summed at the table's own polar angles and at
// azimuths between its samples, against the pointwise BSDF the solver's users evaluate: brdf_surface +
// LayerTables::brdf_subsurface, and LayerTables::btdf. Materials are chosen so that every kind of part appears: the
// surface term, the tables' modes, the unscattered lobe through one interface (matched bottom; open top) and
// through two (the default).
#include "core/series/bsdf_fourier_series.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/conventions.h"
#include "core/interfaces/layer_interfaces.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

double series_sum(std::span<const double> series, double phi) {
  double value = 0.0;
  for (std::size_t k = 0; k < series.size(); ++k) value += series[k] * std::cos(static_cast<double>(k) * phi);
  return value;
}

struct Case {
  const char* name;
  Material material;
};

std::vector<Case> cases() {
  Material skin;
  Material matched;
  matched.sigma = 0.3;
  matched.bottom.kind = BottomKind::Matched;
  Material open_top;
  open_top.eta = 1.0;
  open_top.tau = 0.5;
  open_top.bottom.sigma = 0.25;
  return {
      {"skin (two interfaces)", skin}, {"matched bottom (top only)", matched}, {"open top (bottom only)", open_top}};
}

TEST(BsdfFourierSeries, SumsToThePointwiseBsdfForReflectionAndTransmission) {
  const std::vector<double> theta_i = {0.0, 0.45, 0.9, 1.3};
  const std::vector<double> theta_o = {0.1, 0.6, 1.0, 1.4};
  for (const Case& c : cases()) {
    const std::vector<Material> channels = {c.material, [&] {
                                              Material red = c.material;
                                              red.albedo = 0.7;
                                              return red;
                                            }()};
    const std::vector<LayerTables> tables = solve(std::span<const Material>(channels));
    const RoughDielectric top = top_interface(c.material);
    for (ScatteringKind kind : {ScatteringKind::Reflection, ScatteringKind::Transmission}) {
      const bool reflection = kind == ScatteringKind::Reflection;
      const AzimuthalSeriesTable table = bsdf_fourier_series(top, tables, kind, theta_i, theta_o);
      ASSERT_EQ(table.channels, 2);
      for (int ch = 0; ch < 2; ++ch) {
        const auto bsdf = [&](std::size_t i, std::size_t o, double phi) {
          return reflection ? brdf_surface(channels[ch], theta_i[i], theta_o[o], phi) +
                                  tables[ch].brdf_subsurface(theta_i[i], theta_o[o], phi)
                            : tables[ch].btdf(theta_i[i], theta_o[o], phi);
        };
        double peak = 0.0;
        for (std::size_t i = 0; i < theta_i.size(); ++i) {
          for (std::size_t o = 0; o < theta_o.size(); ++o) peak = std::max(peak, bsdf(i, o, kPi));
        }
        ASSERT_GT(peak, 0.0) << c.name;
        for (std::size_t i = 0; i < theta_i.size(); ++i) {
          for (std::size_t o = 0; o < theta_o.size(); ++o) {
            for (double phi = 0.05; phi < kPi; phi += 0.37) {
              const double want = bsdf(i, o, phi);
              const double got = series_sum(table.series(static_cast<int>(i), static_cast<int>(o), ch), phi);
              const double allowed = want > 1e-3 * peak ? 2e-3 * want : 2e-6 * peak;
              EXPECT_NEAR(got, want, allowed)
                  << c.name << (reflection ? " R" : " T") << " channel " << ch << " theta_i " << theta_i[i]
                  << " theta_o " << theta_o[o] << " phi " << phi;
            }
          }
        }
      }
    }
  }
}

TEST(BsdfFourierSeries, AnOpaqueMaterialTransmitsNothingAndGetsEmptyEntries) {
  Material bone;
  bone.bottom = parse_bottom("lambert:0.6");
  const std::vector<LayerTables> tables = {solve(bone)};
  const std::vector<double> theta = {0.2, 0.8};
  const AzimuthalSeriesTable table =
      bsdf_fourier_series({bone.eta, bone.sigma}, tables, ScatteringKind::Transmission, theta, theta);
  for (int i = 0; i < 2; ++i) {
    for (int o = 0; o < 2; ++o) EXPECT_EQ(table.length(i, o), 0);
  }
}

}  // namespace
}  // namespace skinlayer
