// The skin presets are measured skin (app/presets/skin-*.json): each reproduces the median reflectance spectrum of
// the NIST subjects (tests/reference/nist_skin_reflectance.csv) in its class of individual typology angle, the
// dermatologists' measure of skin colour (Chardon, Cretois & Hourseau 1991, Int. J. Cosmet. Sci. 13:191):
//   ITA = atan((L* - 50) / b*) in degrees, from the CIELAB colour of the reflectance under D65;
// above 41 very light and light, 28-41 intermediate, 10-28 tan, -30-10 brown. The test groups the 50 subjects by
// their measured ITA, takes the median at each wavelength, and compares the preset's spectrum at 8 degrees (the
// integrating sphere's incidence) over 400-700 nm.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "app/material/presets.h"
#include "core/color/ciede2000.h"
#include "core/color/spectral_color.h"
#include "core/conventions.h"
#include "core/fit/skin_fit.h"
#include "tests/core/reference_csv.h"

namespace skinlayer {
namespace {

double typology_angle_degrees(std::span<const double> wavelengths, std::span<const double> reflectance) {
  const Eigen::Vector3d rgb =
      linear_srgb_weights(wavelengths) *
      Eigen::Map<const Eigen::VectorXd>(reflectance.data(), static_cast<Eigen::Index>(reflectance.size()));
  const Eigen::Vector3d lab = linear_srgb_to_lab(rgb);
  return radians_to_degrees(std::atan2(lab(0) - 50.0, lab(2)));
}

struct SkinClass {
  const char* preset;
  std::function<bool(double)> contains;  // of the ITA in degrees
  int subjects;                          // how many of the 50 the class holds
};

TEST(SkinPresets, EachReproducesTheMedianMeasuredSpectrumOfItsColourClass) {
  const test::CsvTable nist = test::read_reference("nist_skin_reflectance.csv");
  std::vector<double> wavelengths;
  std::vector<std::size_t> rows;
  for (std::size_t r = 0; r < nist.rows.size(); ++r) {
    const double w = std::stod(nist.rows[r][0]);
    if (w >= 400.0 && w <= 700.0) {
      wavelengths.push_back(w);
      rows.push_back(r);
    }
  }
  ASSERT_EQ(wavelengths.size(), 101u);
  const std::size_t subjects = nist.header.size() - 1;
  ASSERT_EQ(subjects, 50u);
  std::vector<std::vector<double>> spectra(subjects);
  std::vector<double> ita(subjects);
  for (std::size_t s = 0; s < subjects; ++s) {
    for (const std::size_t r : rows) spectra[s].push_back(std::stod(nist.rows[r][s + 1]));
    ita[s] = typology_angle_degrees(wavelengths, spectra[s]);
  }
  const SkinClass classes[] = {{"skin-fair", [](double a) { return a > 41.0; }, 41},
                               {"skin-medium", [](double a) { return a > 28.0 && a <= 41.0; }, 6},
                               {"skin-dark", [](double a) { return a <= 28.0; }, 3}};
  for (const SkinClass& skin_class : classes) {
    std::vector<double> median;
    int members = 0;
    for (std::size_t k = 0; k < wavelengths.size(); ++k) {
      std::vector<double> values;
      for (std::size_t s = 0; s < subjects; ++s)
        if (skin_class.contains(ita[s])) values.push_back(spectra[s][k]);
      members = static_cast<int>(values.size());
      std::sort(values.begin(), values.end());
      const std::size_t n = values.size();
      median.push_back(n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]));
    }
    EXPECT_EQ(members, skin_class.subjects) << skin_class.preset;

    const MaterialDocument preset = preset_material(skin_class.preset);
    ASSERT_TRUE(preset.skin.has_value()) << skin_class.preset;
    const std::vector<double> model =
        skin_reflectance_spectrum(*preset.skin, preset.layer, wavelengths, degrees_to_radians(8.0), {});
    double sum = 0.0, worst = 0.0;
    for (std::size_t k = 0; k < model.size(); ++k) {
      sum += (model[k] - median[k]) * (model[k] - median[k]);
      worst = std::max(worst, std::abs(model[k] - median[k]));
    }
    const double rms = std::sqrt(sum / static_cast<double>(model.size()));
    EXPECT_LT(rms, 0.007) << skin_class.preset;   // the fits: 0.0052, 0.0036, 0.0018
    EXPECT_LT(worst, 0.02) << skin_class.preset;  // every wavelength: 0.0105, 0.0103, 0.0055
    EXPECT_TRUE(skin_class.contains(typology_angle_degrees(wavelengths, model)))
        << skin_class.preset << ": the preset's own colour falls in its class";
  }
}

}  // namespace
}  // namespace skinlayer
