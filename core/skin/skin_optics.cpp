#include "core/skin/skin_optics.h"

#include <cmath>
#include <limits>

#include "core/data/embedded_table.h"

namespace skinlayer {
namespace {

// ln(10) x 150 g/L / 64,500 g/mol, then 1/cm -> 1/mm: mu_a = kBloodFactor epsilon (epsilon in cm^-1/M).
constexpr double kBloodFactor = 2.302585092994046 * 150.0 / 64500.0 / 10.0;

}  // namespace

double baseline_absorption(double wavelength_nm) { return 0.0244 + 8.53 * std::exp(-(wavelength_nm - 154.0) / 66.2); }

double eumelanin_absorption(double wavelength_nm) { return 6.6e10 * std::pow(wavelength_nm, -3.33); }

double pheomelanin_absorption(double wavelength_nm) { return 2.9e14 * std::pow(wavelength_nm, -4.75); }

double blood_absorption(double wavelength_nm, double oxygenation) {
  const data::EmbeddedTable hemoglobin = data::hemoglobin_prahl();
  const double oxy = hemoglobin.interpolate(1, wavelength_nm);
  const double deoxy = hemoglobin.interpolate(2, wavelength_nm);
  return kBloodFactor * (oxygenation * oxy + (1.0 - oxygenation) * deoxy);
}

LayerOptics epidermis_optics(const SkinParameters& skin, double wavelength_nm) {
  const double melanin = skin.eumelanin * eumelanin_absorption(wavelength_nm) +
                         (1.0 - skin.eumelanin) * pheomelanin_absorption(wavelength_nm);
  return {skin.melanin * melanin + (1.0 - skin.melanin) * baseline_absorption(wavelength_nm),
          skin.scattering * 6.87 * std::pow(wavelength_nm / 500.0, -1.161)};
}

LayerOptics dermis_optics(const SkinParameters& skin, double wavelength_nm) {
  return {skin.blood * blood_absorption(wavelength_nm, skin.oxygenation) +
              (1.0 - skin.blood) * baseline_absorption(wavelength_nm),
          skin.scattering * 4.53 * std::pow(wavelength_nm / 500.0, -1.292)};
}

Material skin_material(const SkinParameters& skin, double wavelength_nm, const Material& interfaces) {
  const LayerOptics epidermis = epidermis_optics(skin, wavelength_nm);
  const LayerOptics dermis = dermis_optics(skin, wavelength_nm);
  Material m;
  m.sigma = interfaces.sigma;
  m.eta = interfaces.eta;
  m.ordinates = interfaces.ordinates;
  m.microfacet = interfaces.microfacet;
  m.extinction = epidermis.extinction();
  m.tau = *m.extinction * skin.epidermis;
  m.albedo = epidermis.albedo();
  m.g = kSkinAnisotropy;
  m.below = {StackedLayer{std::numeric_limits<double>::infinity(), dermis.albedo(), kSkinAnisotropy, std::nullopt,
                          dermis.extinction()}};
  m.bottom.kind = BottomKind::Matched;  // under a semi-infinite dermis the bottom is never reached
  return m;
}

std::vector<double> wavelength_grid(double from_nm, double to_nm, double step_nm) {
  std::vector<double> grid;
  const int count = static_cast<int>(std::floor((to_nm - from_nm) / step_nm + 1e-9)) + 1;
  for (int i = 0; i < count; ++i) grid.push_back(from_nm + i * step_nm);
  return grid;
}

}  // namespace skinlayer
