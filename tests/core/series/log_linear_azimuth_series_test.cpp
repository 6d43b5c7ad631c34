// The cosine series of a lobe sampled in azimuth, exponential between positive samples and linear toward a zero
// (core/series/log_linear_azimuth_series.h):
//  - where the function is an exponential in phi, the interpolant is the function, and each coefficient its closed
//    form (1/pi or 2/pi) (c (e^(c pi) cos m pi - 1)) / (c^2 + m^2);
//  - where a sample is zero the segment is linear, and the coefficients are those of the chord;
//  - every coefficient is the interpolant's own cosine integral (a fine trapezoid rule), and the interpolant passes
//    through the samples, folded onto [0, pi].
#include "core/series/log_linear_azimuth_series.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/conventions.h"

namespace skinlayer {
namespace {

TEST(LogLinearAzimuthSeries, AnExponentialIsItsOwnInterpolant) {
  const std::vector<double> azimuths = {0.0, 0.7, 1.9, 2.6, 3.0, kPi};
  const double c = 1.7;
  Eigen::MatrixXd values(1, static_cast<Eigen::Index>(azimuths.size()));
  for (std::size_t k = 0; k < azimuths.size(); ++k) values(0, static_cast<Eigen::Index>(k)) = std::exp(c * azimuths[k]);
  const LogLinearAzimuthSeries series(azimuths, 40);
  const Eigen::MatrixXd coefficients = series.coefficients(values);
  for (int m = 0; m < 40; ++m) {
    // int_0^pi e^(c phi) cos(m phi) dphi = c (e^(c pi) (-1)^m - 1) / (c^2 + m^2)
    const double integral = c * (std::exp(c * kPi) * (m % 2 ? -1.0 : 1.0) - 1.0) / (c * c + m * m);
    const double expected = (m == 0 ? 1.0 : 2.0) / kPi * integral;
    EXPECT_NEAR(coefficients(0, m), expected, 1e-12 * std::exp(c * kPi)) << "m " << m;
  }
  for (const double phi : {0.3, 1.2, 2.2, 2.8, 3.1}) {
    const std::vector<double> samples(values.row(0).begin(), values.row(0).end());
    EXPECT_NEAR(series.value(samples, phi), std::exp(c * phi), 1e-12 * std::exp(c * phi));
  }
}

TEST(LogLinearAzimuthSeries, ASegmentTowardZeroIsItsChord) {
  const std::vector<double> azimuths = {0.0, 2.0, kPi};
  Eigen::MatrixXd values(1, 3);
  values << 0.0, 0.0, 3.0;  // 0 on [0, 2], then the chord from 0 to 3
  const LogLinearAzimuthSeries series(azimuths, 5);
  const Eigen::MatrixXd coefficients = series.coefficients(values);
  const double slope = 3.0 / (kPi - 2.0);
  // int_2^pi slope (phi - 2) cos(m phi) dphi, closed forms
  EXPECT_NEAR(coefficients(0, 0), 0.5 * 3.0 * (kPi - 2.0) / kPi, 1e-14);
  for (int m = 1; m < 5; ++m) {
    const double a = 2.0, b = kPi, mm = m;
    const double integral = slope * ((b - a) * std::sin(mm * b) / mm + (std::cos(mm * b) - std::cos(mm * a)) / (mm * mm));
    EXPECT_NEAR(coefficients(0, m), 2.0 / kPi * integral, 1e-14) << "m " << m;
  }
  const std::vector<double> row(values.row(0).begin(), values.row(0).end());
  EXPECT_NEAR(series.value(row, 2.5), slope * 0.5, 1e-14);
  EXPECT_EQ(series.value(row, 1.0), 0.0);
}

// A lobe like the multiply scattered light's: sharp at the forward plane, with a tail, samples closest at pi.
TEST(LogLinearAzimuthSeries, EveryModeIsTheInterpolantsCosineIntegral) {
  const std::vector<double> degrees = {0, 15, 30, 45, 60, 75, 90, 105, 120, 133, 145, 155, 163, 169, 173.5, 176.5,
                                       178.5, 179.5, 180};
  std::vector<double> azimuths;
  Eigen::MatrixXd values(2, static_cast<Eigen::Index>(degrees.size()));
  for (std::size_t k = 0; k < degrees.size(); ++k) {
    azimuths.push_back(degrees[k] * kPi / 180.0);
    const double from_forward = kPi - azimuths.back();
    values(0, static_cast<Eigen::Index>(k)) = std::exp(-from_forward * from_forward / 0.01) + 1e-3 * std::cos(azimuths.back());
    values(1, static_cast<Eigen::Index>(k)) = k < 4 ? 0.0 : 0.2 + std::exp(-from_forward / 0.3);
  }
  values = values.cwiseMax(0.0);
  const LogLinearAzimuthSeries series(azimuths, 64);
  const Eigen::MatrixXd coefficients = series.coefficients(values);
  constexpr int kSteps = 180000;
  for (Eigen::Index f = 0; f < 2; ++f) {
    const std::vector<double> samples(values.row(f).begin(), values.row(f).end());
    const std::span<const double> row(samples);
    std::vector<double> sampled(kSteps + 1);
    for (int k = 0; k <= kSteps; ++k) sampled[static_cast<std::size_t>(k)] = series.value(row, kPi * k / kSteps);
    for (const int m : {0, 1, 2, 9, 30, 63}) {
      double integral = 0.0;
      for (int k = 0; k <= kSteps; ++k) {
        const double weight = (k == 0 || k == kSteps ? 0.5 : 1.0) * kPi / kSteps;
        integral += weight * sampled[static_cast<std::size_t>(k)] * std::cos(m * kPi * k / kSteps);
      }
      EXPECT_NEAR(coefficients(f, m), (m == 0 ? 1.0 : 2.0) / kPi * integral, 1e-7) << "function " << f << " m " << m;
    }
    for (std::size_t k = 0; k < degrees.size(); ++k) {
      EXPECT_DOUBLE_EQ(series.value(row, azimuths[k]), row[k]);
      EXPECT_DOUBLE_EQ(series.value(row, -azimuths[k]), row[k]);  // even
      EXPECT_NEAR(series.value(row, 2.0 * kPi - azimuths[k]), row[k], 1e-12 * (1.0 + row[k]));
    }
  }
}

TEST(LogLinearAzimuthSeries, NoLightHasNoModes) {
  const std::vector<double> azimuths = {0.0, 1.0, kPi};
  const LogLinearAzimuthSeries series(azimuths, 8);
  EXPECT_EQ(series.modes(), 8);
  EXPECT_EQ(series.coefficients(Eigen::MatrixXd::Zero(3, 3)).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(LogLinearAzimuthSeries(azimuths, 0).coefficients(Eigen::MatrixXd::Ones(2, 3)).cols(), 0);
}

}  // namespace
}  // namespace skinlayer
