// solve_color of a spectral skin: each channel's tables and albedo are the linear-sRGB mix of the per-wavelength
// solves (app/material/color_channels.h), built here independently from core: the skin's layers at each wavelength,
// solved alone on the same table grid, weighted by the CIE/D65 sRGB weights. The surface term is shared. Energy
// holds in every channel, and the preview solves the coarser wavelength grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "app/material/color_channels.h"
#include "app/solution/material_solve.h"
#include "core/color/spectral_color.h"
#include "core/conventions.h"
#include "core/series/quadrature.h"
#include "core/skin/skin_optics.h"
#include "core/solve/resolution.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

ColorMaterial a_skin() {
  ColorMaterial material;
  material.layer.sigma = 0.35;
  material.layer.eta = 1.4;
  material.skin = SkinParameters{};
  material.skin->melanin = 0.06;
  material.skin->blood = 0.02;
  return material;
}

TEST(SpectralColorSolve, EachChannelIsTheWeightedSumOfTheWavelengthsSolves) {
  const ColorMaterial material = a_skin();
  const double theta_i = 0.5;
  const ColorTables tables = solve_color(material, theta_i);

  const std::vector<double> wavelengths = wavelength_grid(400.0, 700.0, 10.0);
  const Eigen::Matrix<double, 3, Eigen::Dynamic> weights = linear_srgb_weights(wavelengths);
  std::vector<Material> layers;
  SolveOptions options;
  for (const double w : wavelengths) {
    layers.push_back(skin_material(*material.skin, w, material.layer));
    options.table_size = std::max(options.table_size, choose_resolution(layers.back()).table_size);
  }
  std::vector<LayerTables> solved;
  std::vector<DirectionalAlbedo> albedo;
  const double thetas[1] = {theta_i};
  for (const Material& m : layers) {
    solved.push_back(solve(m, options));
    albedo.push_back(directional_albedo(m, thetas).front());
  }

  std::mt19937 random(11);
  std::uniform_real_distribution<double> polar(0.0, 1.5), azimuth(0.0, 3.14159);
  for (int n = 0; n < 100; ++n) {
    const double ti = polar(random), to = polar(random), phi = azimuth(random);
    for (int c = 0; c < 3; ++c) {
      double subsurface = 0.0;
      for (std::size_t k = 0; k < solved.size(); ++k)
        subsurface += weights(c, k) * solved[k].brdf_subsurface(ti, to, phi);
      const double expected = brdf_surface(material.layer, ti, to, phi) + subsurface;
      EXPECT_NEAR(brdf_total(tables, c, ti, to, phi), expected, 1e-10 * expected) << ti << " " << to << " " << c;
      EXPECT_EQ(btdf_total(tables, c, ti, to, phi), 0.0);  // the dermis is semi-infinite
    }
  }
  const Eigen::Vector3d reflectance = [&] {
    Eigen::VectorXd per_wavelength(static_cast<Eigen::Index>(albedo.size()));
    for (std::size_t k = 0; k < albedo.size(); ++k)
      per_wavelength(static_cast<Eigen::Index>(k)) = albedo[k].reflectance();
    return Eigen::Vector3d(weights * per_wavelength);
  }();
  for (int c = 0; c < 3; ++c) {
    const DirectionalAlbedo& a = tables.albedo[c];
    EXPECT_NEAR(a.reflectance(), reflectance(c), 1e-12);
    EXPECT_NEAR(a.reflectance() + a.transmittance + a.absorptance, 1.0, 1e-9);
  }
  // A skin's colour: red above green above blue, each channel its own table.
  EXPECT_GT(tables.albedo[0].reflectance(), tables.albedo[1].reflectance());
  EXPECT_GT(tables.albedo[1].reflectance(), tables.albedo[2].reflectance());
}

// The subsurface reflectance at theta_i that a channel's table holds: 2 pi int S_0(theta_i, theta) cos sin d theta,
// and its unscattered light's (the top's multiply scattered reflection, not uniform in azimuth), 2 int_0^pi over phi.
double table_reflectance(const LayerTables& table, double theta_i) {
  const QuadratureRule theta = gauss_legendre(96, 0.0, 0.5 * kPi);
  const QuadratureRule phi = gauss_legendre(96, 0.0, kPi);
  double sum = 0.0;
  for (int a = 0; a < theta.size(); ++a) {
    const double t = theta.nodes[a];
    double unscattered = 0.0;
    for (int b = 0; b < phi.size(); ++b) {
      unscattered += 2.0 * phi.weights[b] * table.unscattered().brdf(theta_i, t, phi.nodes[b]);
    }
    sum +=
        theta.weights[a] * std::cos(t) * std::sin(t) * (2.0 * kPi * table.reflection_mode(0, theta_i, t) + unscattered);
  }
  return sum;
}

// The preview tabulates 7 wavelengths but reports, and scales its tables to, the colour of all 31: its energy
// readout and its tables' reflectance at the light's angle are the full solve's within the preview resolution's
// error, where the 7 wavelengths alone would be 5-6% off in red and green for this skin.
TEST(SpectralColorSolve, ThePreviewTabulatesFewerWavelengthsButShowsTheFullColour) {
  const ColorMaterial material = a_skin();
  const double theta_i = 0.6;
  SolveOptions preview;
  preview.preview = true;
  const ColorTables coarse = solve_color(material, theta_i, preview);
  const ColorTables full = solve_color(material, theta_i);
  EXPECT_EQ(skin_preview_wavelengths().size(), 7u);
  for (int c = 0; c < 3; ++c) {
    const double f = full.albedo[c].reflectance_subsurface, p = coarse.albedo[c].reflectance_subsurface;
    const double shown = table_reflectance(coarse.channels[c], theta_i);
    const double full_shown = table_reflectance(full.channels[c], theta_i);
    std::printf("channel %d: subsurface reflectance full %.5f (its table %.5f), preview %.5f (its table %.5f)\n", c, f,
                full_shown, p, shown);
    EXPECT_NEAR(p, f, 0.01 * f);
    EXPECT_NEAR(shown, p, 1e-3 * p);  // the scaled table holds the reported reflectance
    EXPECT_NEAR(full_shown, f, 1e-3 * f);
  }
}

}  // namespace
}  // namespace skinlayer
