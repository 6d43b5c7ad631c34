// Smith masking-shadowing of two directions (core/interfaces/smith_masking.h): the separable form is the product of
// the G1; the height-correlated form has its closed forms (1 / (1 + Li + Lo); the Beta function), reflects at least
// as much and transmits at most as much as the separable one, and equals it when one direction is never masked.
#include "core/interfaces/smith_masking.h"

#include <gtest/gtest.h>

namespace skinlayer {
namespace {

TEST(SmithMasking, TheSeparableFormIsTheProduct) {
  for (const double a : {0.0, 0.3, 0.9, 1.0}) {
    for (const double b : {0.2, 0.7, 1.0}) {
      EXPECT_EQ(smith_g2_reflection(a, b, MicrofacetModel::Single), a * b);
      EXPECT_EQ(smith_g2_transmission(a, b, MicrofacetModel::Single), a * b);
    }
  }
}

TEST(SmithMasking, TheHeightCorrelatedFormHasItsClosedForms) {
  // G1 = 1/2: Lambda = 1 on both directions.
  EXPECT_NEAR(smith_g2_reflection(0.5, 0.5, MicrofacetModel::Multiple), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(smith_g2_transmission(0.5, 0.5, MicrofacetModel::Multiple), 1.0 / 6.0, 1e-14);  // B(2, 2)
  // G1 = 1/3 and 1/2: Lambda 2 and 1; B(3, 2) = 1/12.
  EXPECT_NEAR(smith_g2_transmission(1.0 / 3.0, 0.5, MicrofacetModel::Multiple), 1.0 / 12.0, 1e-14);
  EXPECT_NEAR(smith_g2_reflection(1.0 / 3.0, 0.5, MicrofacetModel::Multiple), 0.25, 1e-15);
  EXPECT_EQ(smith_g2_reflection(0.0, 0.5, MicrofacetModel::Multiple), 0.0);
  EXPECT_EQ(smith_g2_transmission(0.5, 0.0, MicrofacetModel::Multiple), 0.0);
}

TEST(SmithMasking, CorrelationKeepsReflectionAndLosesTransmission) {
  for (const double a : {0.05, 0.3, 0.8, 0.99}) {
    for (const double b : {0.1, 0.6, 0.95}) {
      EXPECT_GT(smith_g2_reflection(a, b, MicrofacetModel::Multiple), a * b) << a << " " << b;
      EXPECT_LT(smith_g2_transmission(a, b, MicrofacetModel::Multiple), a * b) << a << " " << b;
      EXPECT_LE(smith_g2_reflection(a, b, MicrofacetModel::Multiple), std::min(a, b) + 1e-15);
    }
    // A direction that nothing masks (G1 = 1) leaves the other's G1.
    EXPECT_NEAR(smith_g2_reflection(1.0, a, MicrofacetModel::Multiple), a, 1e-15);
    EXPECT_NEAR(smith_g2_transmission(a, 1.0, MicrofacetModel::Multiple), a, 1e-14);
  }
}

TEST(MicrofacetModel, NamesRoundTrip) {
  for (const MicrofacetModel model : {MicrofacetModel::Single, MicrofacetModel::Multiple}) {
    EXPECT_EQ(parse_microfacet_model(microfacet_model_name(model)), model);
  }
  EXPECT_FALSE(parse_microfacet_model("double").has_value());
}

}  // namespace
}  // namespace skinlayer
