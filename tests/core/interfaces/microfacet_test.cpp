#include "core/interfaces/microfacet.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/conventions.h"
#include "core/interfaces/fresnel.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

// int over the upper hemisphere of f(theta, phi) d omega, by Gauss-Legendre in cos(theta) and phi.
template <class F>
double integrate_hemisphere(const F& f, int n_theta = 400, int n_phi = 200) {
  const QuadratureRule mu = gauss_legendre(n_theta, 0.0, 1.0);
  const QuadratureRule phi = gauss_legendre(n_phi, 0.0, 2.0 * kPi);
  double sum = 0.0;
  for (int a = 0; a < mu.size(); ++a) {
    for (int b = 0; b < phi.size(); ++b) sum += mu.weights[a] * phi.weights[b] * f(std::acos(mu.nodes[a]), phi.nodes[b]);
  }
  return sum;
}

TEST(BeckmannNdf, ProjectedAreaIntegratesToOne) {
  for (double sigma : {0.1, 0.3, 0.5, 1.0}) {
    const double total = integrate_hemisphere(
        [sigma](double theta, double) { return beckmann_ndf(std::cos(theta), sigma) * std::cos(theta); }, 2000, 4);
    EXPECT_NEAR(total, 1.0, 1e-6) << sigma;
  }
}

TEST(BeckmannNdf, PeakValueAtNormal) {
  EXPECT_NEAR(beckmann_ndf(1.0, 0.35), 1.0 / (kPi * 0.35 * 0.35), 1e-12);
  EXPECT_EQ(beckmann_ndf(-0.5, 0.35), 0.0);
}

// Smith's Lambda is defined by  int max(0, w.h) D(h) d omega_h = cos(theta_w) (1 + Lambda(w)).
TEST(SmithG1Beckmann, ClosedFormMatchesItsDefiningIntegral) {
  for (double sigma : {0.2, 0.5, 1.0}) {
    for (double theta_deg : {10.0, 45.0, 70.0, 85.0}) {
      const Vec3 w = direction_from_angles(degrees_to_radians(theta_deg), 0.0);
      const double projected = integrate_hemisphere(
          [&](double theta, double phi) {
            const Vec3 h = direction_from_angles(theta, phi);
            return std::max(0.0, w.dot(h)) * beckmann_ndf(h.z(), sigma);
          },
          1200, 400);
      const double lambda_numeric = projected / w.z() - 1.0;
      const double g1 = smith_g1_beckmann(w.z(), sigma);
      EXPECT_NEAR(1.0 / g1 - 1.0, lambda_numeric, 2e-4 * (1.0 + lambda_numeric))
          << "sigma " << sigma << " theta " << theta_deg;
    }
  }
  EXPECT_EQ(smith_g1_beckmann(1.0, 0.5), 1.0);
  EXPECT_EQ(smith_g1_beckmann(0.0, 0.5), 0.0);
}

TEST(MicrofacetBrdf, NormalIncidenceValue) {
  // Spec sanity check: F(1.4) D(0) / 4 with D(0) = 1/(pi sigma^2) and G = 1 at normal incidence.
  const RoughDielectric interface{1.4, 0.35};
  const Vec3 n(0, 0, 1);
  EXPECT_NEAR(microfacet_brdf(interface, n, n), 0.0277777777777 / (kPi * 0.35 * 0.35) / 4.0, 1e-9);
  EXPECT_NEAR(microfacet_brdf(interface, n, n), 0.01805, 1e-4);
}

TEST(MicrofacetBrdf, IsSymmetricAndZeroAtIndexMatch) {
  const RoughDielectric interface{1.4, 0.4};
  for (double ti : {0.1, 0.7, 1.3}) {
    for (double to : {0.2, 0.9, 1.5}) {
      for (double phi : {0.0, 1.0, 3.0}) {
        const Vec3 a = direction_from_angles(ti, 0.0);
        const Vec3 b = direction_from_angles(to, phi);
        EXPECT_NEAR(microfacet_brdf(interface, a, b), microfacet_brdf(interface, b, a), 1e-14);
        EXPECT_NEAR(microfacet_brdf(interface, -a, -b), microfacet_brdf(interface, -b, -a), 1e-14);
        EXPECT_EQ(microfacet_brdf({1.0, 0.4}, a, b), 0.0);
      }
    }
  }
}

// Generalized reciprocity of the radiance BTDF: f_t(a -> b) / n_b^2 = f_t(b -> a) / n_a^2.
TEST(MicrofacetBtdf, GeneralizedReciprocity) {
  const double eta = 1.4;
  const RoughDielectric interface{eta, 0.5};
  for (double ti : {0.1, 0.6, 1.2, 1.5}) {
    for (double to : {0.05, 0.5, 1.0, 1.4}) {
      for (double phi : {0.0, 0.8, 2.5, 3.1}) {
        const Vec3 above = direction_from_angles(ti, 0.0);
        const Vec3 below = -direction_from_angles(to, phi);
        const double down = microfacet_btdf(interface, above, below);  // light from air into the layer
        const double up = microfacet_btdf(interface, below, above);    // light from the layer into air
        EXPECT_NEAR(down / (eta * eta), up, 1e-12 * (1.0 + up));
      }
    }
  }
}

TEST(MicrofacetBtdf, MatchesWalterFormWithIndependentHalfVector) {
  // Walter et al. 2007 eq. 21 with h_t = -(n_i wi + n_o wo) written out independently.
  const double n_i = 1.0, n_o = 1.4, sigma = 0.3;
  const Vec3 wi = direction_from_angles(0.6, 0.0);
  const Vec3 wo = -direction_from_angles(0.35, 0.2);  // below, roughly straight through
  Vec3 h = -(n_i * wi + n_o * wo);
  h.normalize();
  const double i_h = wi.dot(h), o_h = wo.dot(h);
  const double expected = std::abs(i_h) * std::abs(o_h) / (wi.z() * std::abs(wo.z())) * n_o * n_o *
                          (1.0 - fresnel_dielectric(i_h, n_o / n_i)) * beckmann_ndf(h.z(), sigma) *
                          smith_g1_beckmann(wi.z(), sigma) * smith_g1_beckmann(wo.z(), sigma) /
                          std::pow(n_i * i_h + n_o * o_h, 2);
  ASSERT_GT(expected, 0.1);
  EXPECT_NEAR(microfacet_btdf({n_o / n_i, sigma}, wi, wo), expected, 1e-12 * expected);
}

TEST(RoughDielectric, NeverCreatesEnergy) {
  for (double eta : {1.4, 2.5}) {
    for (double sigma : {0.1, 0.5, 1.0}) {
      const RoughDielectric interface{eta, sigma};
      for (double side : {1.0, -1.0}) {
        for (double theta : {0.0, 0.5, 1.0, 1.4, 1.55}) {
          const Vec3 wi = side * direction_from_angles(theta, 0.0);
          const double reflected = integrate_hemisphere([&](double t, double p) {
            const Vec3 wo = side * direction_from_angles(t, p);
            return microfacet_brdf(interface, wi, wo) * std::cos(t);
          });
          const double transmitted = integrate_hemisphere([&](double t, double p) {
            const Vec3 wo = -side * direction_from_angles(t, p);
            return microfacet_btdf(interface, wi, wo) * std::cos(t);
          });
          EXPECT_LE(reflected + transmitted, 1.0 + 2e-3)
              << "eta " << eta << " sigma " << sigma << " side " << side << " theta " << theta;
          EXPECT_GE(reflected, 0.0);
          EXPECT_GE(transmitted, 0.0);
        }
      }
    }
  }
}

TEST(RoughDielectric, TotalInternalReflectionSendsNothingOutAtGrazingInsideForSmoothSurface) {
  // Nearly smooth surface, light inside travelling past the critical angle (asin(1/1.4) = 45.6 deg): the transmitted
  // lobe vanishes while the mirror reflection carries everything.
  const RoughDielectric interface{1.4, 0.05};
  const Vec3 wi = -direction_from_angles(degrees_to_radians(70.0), 0.0);  // inside, below the interface
  const double transmitted = integrate_hemisphere([&](double t, double p) {
    return microfacet_btdf(interface, wi, direction_from_angles(t, p)) * std::cos(t);
  });
  EXPECT_LT(transmitted, 1e-6);
}

}  // namespace
}  // namespace skinlayer
