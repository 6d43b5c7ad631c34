// The skin's optical properties (core/skin/skin_optics.h) against hand computations from the cited formulas (the
// numbers below were worked out apart from the code, from the published constants and Prahl's table rows), and
// the spectral solve (core/skin/skin_spectrum.h) against energy bookkeeping and the known features of skin spectra.
#include "core/skin/skin_optics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/color/spectral_color.h"
#include "core/conventions.h"
#include "core/reference/monte_carlo.h"
#include "core/skin/skin_spectrum.h"

namespace skinlayer {
namespace {

TEST(SkinOptics, ChromophoreAbsorptionMatchesHandComputations) {
  // Jacques' baseline in 1/mm (his 1/cm values 2.32, 0.702, 0.345, 0.266 at 400-700 nm).
  EXPECT_NEAR(baseline_absorption(400), 0.231942, 1e-6);
  EXPECT_NEAR(baseline_absorption(500), 0.0702217, 1e-7);
  EXPECT_NEAR(baseline_absorption(700), 0.0266336, 1e-7);
  // The melanin power laws.
  EXPECT_NEAR(eumelanin_absorption(500), 67.9163, 1e-3);
  EXPECT_NEAR(pheomelanin_absorption(500), 43.8824, 1e-3);
  EXPECT_NEAR(eumelanin_absorption(700), 22.1497, 1e-3);
  // Whole blood: ln(10) 150 / 64500 epsilon, in 1/mm. At 542 nm (a table row) with S = 0.75:
  // 0.75 x 53292 + 0.25 x 48148 = 52006 -> 27.8484 1/mm; oxy-hemoglobin alone there gives the 28.5 1/cm x 10.
  EXPECT_NEAR(blood_absorption(542, 0.75), 27.8484, 1e-3);
  EXPECT_NEAR(blood_absorption(542, 1.0), 28.5371, 1e-3);
  EXPECT_NEAR(blood_absorption(560, 0.0), 28.8027, 1e-3);
}

TEST(SkinOptics, LayerPropertiesMatchHandComputations) {
  const SkinParameters skin;  // melanin 2%, eumelanin 0.7, blood 0.5%, S 0.75, 60 um, scattering 1
  const LayerOptics epidermis = epidermis_optics(skin, 450);
  EXPECT_NEAR(epidermis.absorption, 1.904217, 1e-5);
  EXPECT_NEAR(epidermis.scattering(), 38.81961, 1e-4);
  const LayerOptics dermis = dermis_optics(skin, 600);
  EXPECT_NEAR(dermis.absorption, 0.0505942, 1e-6);
  EXPECT_NEAR(dermis.scattering(), 17.89641, 1e-4);
  const Material m = skin_material(skin, 450);
  EXPECT_NEAR(m.tau, 2.443430, 1e-5);
  EXPECT_NEAR(m.albedo, 0.9532407, 1e-6);
  EXPECT_EQ(m.g, kSkinAnisotropy);
  ASSERT_EQ(m.below.size(), 1u);
  EXPECT_TRUE(std::isinf(m.below[0].tau));
  EXPECT_FALSE(m.below[0].interface.has_value());
  EXPECT_NEAR(skin_material(skin, 600).below[0].albedo, 0.99718091, 1e-7);
  // Each layer carries its extinction mu_a + mu_s, so the epidermis is the parameter's 60 um thick.
  EXPECT_NEAR(*m.extinction, 1.904217 + 38.81961, 2e-4);
  EXPECT_NEAR(*layer_thickness_mm(stack_layers(m)[0]), skin.epidermis, 1e-15);
  EXPECT_NEAR(*skin_material(skin, 600).below[0].extinction, 0.0505942 + 17.89641, 2e-4);
  SkinParameters doubled = skin;
  doubled.scattering = 2.0;
  EXPECT_NEAR(epidermis_optics(doubled, 450).scattering(), 2.0 * epidermis.scattering(), 1e-12);
}

TEST(SkinParameters, BadValuesNameTheParameterAndItsRange) {
  SkinParameters skin;
  skin.blood = 0.3;
  try {
    validate(skin);
    FAIL() << "blood 0.3 accepted";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("blood"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("[0, 0.2]"), std::string::npos) << e.what();
  }
  skin = {};
  skin.melanin = std::nan("");
  EXPECT_THROW(validate(skin), ParameterError);
  EXPECT_THROW(skin_parameter_info("melanine"), std::invalid_argument);
}

// Reflectance (surface and subsurface) of skin at 8 degrees, the integrating sphere's geometry.
std::map<double, double> reflectance_at(const SkinParameters& skin, const std::vector<double>& wavelengths) {
  const double theta[] = {degrees_to_radians(8.0)};
  const auto rows = skin_directional_albedo(skin, Material{}, wavelengths, theta);
  std::map<double, double> result;
  for (std::size_t k = 0; k < wavelengths.size(); ++k) result[wavelengths[k]] = rows[k][0].reflectance();
  return result;
}

TEST(SkinSpectrum, EnergyIsAccountedForAtEveryWavelength) {
  const std::vector<double> wavelengths = {400, 450, 542, 577, 650, 700};
  const double theta[] = {0.0, degrees_to_radians(45.0), degrees_to_radians(80.0)};
  const auto rows = skin_directional_albedo(SkinParameters{}, Material{}, wavelengths, theta);
  for (const auto& per_angle : rows) {
    for (const DirectionalAlbedo& row : per_angle) {
      EXPECT_NEAR(row.reflectance() + row.transmittance + row.absorptance, 1.0, 1e-12);
      EXPECT_NEAR(row.transmittance, 0.0, 1e-12);  // semi-infinite dermis
      ASSERT_EQ(row.layer_absorptance.size(), 2u);
      // What the two media absorb and the interface's shadowing make up the absorptance.
      EXPECT_NEAR(row.layer_absorptance[0] + row.layer_absorptance[1] + row.interface_loss, row.absorptance, 1e-6);
      EXPECT_GT(row.layer_absorptance[0], 0.0);
      EXPECT_GT(row.layer_absorptance[1], 0.0);
    }
  }
}

TEST(SkinSpectrum, OxyHemoglobinBandsShowAsTwoDipsAndTheRedRises) {
  SkinParameters light;
  light.melanin = 0.01;
  light.blood = 0.02;
  light.oxygenation = 0.98;
  auto r = reflectance_at(light, {530, 542, 560, 577, 592, 620, 660});
  EXPECT_LT(r[542], r[530]);  // the beta band
  EXPECT_LT(r[542], r[560]);
  EXPECT_LT(r[577], r[560]);  // the alpha band
  EXPECT_LT(r[577], r[592]);
  EXPECT_GT(r[620], 1.2 * r[577]);  // past 600 nm blood absorbs little
  EXPECT_GT(r[660], r[620]);
}

TEST(SkinSpectrum, MelaninLowersBlueMoreThanRedAndLightSkinIsRedderThanBlue) {
  const std::vector<double> grid = wavelength_grid(400, 700, 20);
  const Eigen::Matrix<double, 3, Eigen::Dynamic> weights = linear_srgb_weights(grid);
  const auto rgb = [&](const SkinParameters& skin) {
    const std::map<double, double> r = reflectance_at(skin, grid);
    Eigen::VectorXd spectrum(static_cast<Eigen::Index>(grid.size()));
    for (std::size_t k = 0; k < grid.size(); ++k) spectrum(static_cast<Eigen::Index>(k)) = r.at(grid[k]);
    return Eigen::Vector3d(weights * spectrum);
  };
  SkinParameters light;
  light.melanin = 0.02;
  SkinParameters dark = light;
  dark.melanin = 0.3;
  const Eigen::Vector3d fair = rgb(light), deep = rgb(dark);
  EXPECT_GT(fair(0), fair(1));
  EXPECT_GT(fair(1), fair(2));
  EXPECT_LT(deep(2) / fair(2), deep(0) / fair(0));  // blue falls by the larger factor
  EXPECT_LT(deep(0), fair(0));
}

// The spectral stack against the independent Monte Carlo reference (core/reference/monte_carlo.h), where blood
// absorbs strongly (420 nm, the Soret band) and weakly (560 nm, between the bands, a long random walk in the dermis).
TEST(SkinSpectrum, AgreesWithMonteCarloAtStrongAndWeakAbsorption) {
  SkinParameters skin;
  skin.blood = 0.02;
  for (const double wavelength : {420.0, 560.0}) {
    const Material material = skin_material(skin, wavelength);
    const double theta = degrees_to_radians(30.0);
    MonteCarloOptions options;
    options.paths = 300000;
    options.seed = static_cast<std::uint64_t>(wavelength);
    const MonteCarloResult mc = simulate_layer(material, theta, {}, options);
    const double angles[] = {theta};
    const DirectionalAlbedo solver = directional_albedo(material, angles).front();
    const auto agrees = [&](const char* what, const MonteCarloEstimate& estimate, double value) {
      EXPECT_LE(std::abs(estimate.value - value), 4.0 * estimate.standard_error + 0.003 * value)
          << what << " at " << wavelength << " nm: Monte Carlo " << estimate.value << " +- " << estimate.standard_error
          << ", solver " << value;
    };
    agrees("reflectance_surface", mc.reflectance_surface, solver.reflectance_surface);
    agrees("reflectance_subsurface", mc.reflectance_subsurface, solver.reflectance_subsurface);
    EXPECT_EQ(mc.truncated_paths, 0u);
  }
}

}  // namespace
}  // namespace skinlayer
