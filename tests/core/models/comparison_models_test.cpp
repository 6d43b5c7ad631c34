// The comparison models of Stam's results slides: Lambert and Hanrahan-Krueger (single scattering), checked against
// the layer solver in the limits where they must agree, and where they must not.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "core/conventions.h"
#include "core/models/hanrahan_krueger.h"
#include "core/models/lambert_model.h"
#include "core/models/subsurface_model.h"
#include "core/series/quadrature.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

// int f_sub(theta_i, omega_o) cos(theta_o) d omega_o by Gauss-Legendre in theta_o and phi.
template <class F>
double hemispherical(const F& f, double theta_i) {
  const QuadratureRule theta = gauss_legendre(64, 0.0, 0.5 * kPi);
  const QuadratureRule phi = gauss_legendre(64, 0.0, 2.0 * kPi);
  double sum = 0.0;
  for (int a = 0; a < theta.size(); ++a) {
    for (int b = 0; b < phi.size(); ++b) {
      const double t = theta.nodes[a];
      sum += theta.weights[a] * phi.weights[b] * std::sin(t) * std::cos(t) * f(theta_i, t, phi.nodes[b]);
    }
  }
  return sum;
}

Material index_matched(double tau, double albedo, double g) {
  Material m;
  m.eta = 1.0;
  m.tau = tau;
  m.albedo = albedo;
  m.g = g;
  m.bottom = parse_bottom("matched");
  return m;
}

TEST(HanrahanKrueger, AgreesWithTheSolverInTheSingleScatteringLimit) {
  for (double g : {0.0, 0.5}) {
    const Material m = index_matched(1e-3, 0.9, g);
    const LayerTables tables = solve(m);
    for (double ti : {0.0, 0.5, 1.0}) {
      for (double to : {0.2, 0.7, 1.2}) {
        for (double phi : {0.0, 1.5, kPi}) {
          const double solver_r = tables.brdf_subsurface(ti, to, phi);
          EXPECT_NEAR(hanrahan_krueger_brdf_subsurface(m, ti, to, phi), solver_r, 1e-2 * solver_r);
          const double solver_t = tables.btdf(ti, to, phi);
          EXPECT_NEAR(hanrahan_krueger_btdf(m, ti, to, phi), solver_t, 1e-2 * solver_t);
        }
      }
    }
  }
}

// A thick, bright layer sends back mostly light scattered many times, which single scattering lacks. Semi-infinite,
// Omega = 0.99, index-matched, normal incidence: the solver's albedo is 0.753 (isotropic) and 0.522 (g = 0.8); the
// single-scattering model returns 0.152 (the closed form Omega (1 - ln 2) / 2) and 0.013: 20% and 2.5% of the
// solver's. The test requires less than a quarter.
TEST(HanrahanKrueger, FallsFarBelowTheSolverForThickBrightLayers) {
  for (double g : {0.0, 0.8}) {
    const Material m = index_matched(INFINITY, 0.99, g);
    const double solver = directional_albedo(m, std::vector<double>{0.0})[0].reflectance_subsurface;
    const double hk = hemispherical(
        [&m](double ti, double to, double phi) { return hanrahan_krueger_brdf_subsurface(m, ti, to, phi); }, 0.0);
    EXPECT_LT(hk, 0.25 * solver) << "g " << g << ": HK " << hk << " solver " << solver;
    EXPECT_GT(hk, 0.0);
    if (g == 0.0) {
      EXPECT_NEAR(hk, 0.5 * 0.99 * (1.0 - std::log(2.0)), 2e-3);  // closed form of the isotropic case
    }
    std::printf("g %.1f: single scattering %.4f, solver %.4f, ratio %.3f\n", g, hk, solver, hk / solver);
  }
}

TEST(HanrahanKrueger, IsReciprocalAndUsesFresnelAtTheBoundary) {
  Material m;  // eta 1.4: refracted angles and Fresnel transmission on both sides
  m.g = 0.3;
  for (double ti : {0.1, 0.8, 1.3}) {
    for (double to : {0.3, 1.0, 1.5}) {
      EXPECT_NEAR(hanrahan_krueger_brdf_subsurface(m, ti, to, 2.0), hanrahan_krueger_brdf_subsurface(m, to, ti, 2.0),
                  1e-12);
    }
  }
  Material denser = m;
  denser.eta = 2.5;  // more Fresnel reflection, less light in and out
  EXPECT_LT(hanrahan_krueger_brdf_subsurface(denser, 0.3, 0.3, kPi) * 2.5 * 2.5,
            hanrahan_krueger_brdf_subsurface(m, 0.3, 0.3, kPi) * 1.4 * 1.4);
}

TEST(LambertModel, AlbedoIsTheLayersAtNormalIncidenceAndIsReturnedAtEveryIncidence) {
  for (const char* bottom : {"air", "lambert:0.5", "matched"}) {
    Material m;
    m.bottom = parse_bottom(bottom);
    m.albedo = 0.9;
    const LambertModel lambert = lambert_model_for(m);
    const double layer = directional_albedo(m, std::vector<double>{0.0})[0].reflectance_subsurface;
    EXPECT_NEAR(lambert.albedo, layer, 1e-12);
    for (double ti : {0.0, 0.6, 1.2}) {
      const double returned = hemispherical([&](double, double, double) { return lambert.brdf_subsurface(); }, ti);
      EXPECT_NEAR(returned, lambert.albedo, 1e-9) << bottom;
    }
  }
}

TEST(LambertModel, TotalBrdfIsReciprocal) {
  Material m;
  const LambertModel lambert = lambert_model_for(m);
  for (double ti : {0.1, 0.8, 1.3}) {
    for (double to : {0.3, 1.0, 1.5}) {
      const double forward = brdf_surface(m, ti, to, 2.5) + lambert.brdf_subsurface();
      const double backward = brdf_surface(m, to, ti, 2.5) + lambert.brdf_subsurface();
      EXPECT_NEAR(forward, backward, 1e-12 * forward);
    }
  }
}

}  // namespace
}  // namespace skinlayer

namespace skinlayer {
namespace {

// Every model as tables: the same evaluation path as the layer's, within the spline and truncation tolerance.
TEST(SubsurfaceModel, TablesReproduceEachModel) {
  Material m;
  m.g = 0.5;
  const LayerTables hk = solve_model(m, SubsurfaceModel::HanrahanKrueger);
  const LayerTables lambert = solve_model(m, SubsurfaceModel::Lambert);
  const double diffuse = lambert_model_for(m).brdf_subsurface();
  for (double ti : {0.0, 0.4, 0.9, 1.3}) {
    for (double to : {0.1, 0.6, 1.1}) {
      for (double phi : {0.0, 1.0, 2.0, kPi}) {
        const double expected_r = hanrahan_krueger_brdf_subsurface(m, ti, to, phi);
        const double expected_t = hanrahan_krueger_btdf(m, ti, to, phi);
        EXPECT_NEAR(hk.brdf_subsurface(ti, to, phi), expected_r, 5e-3 * expected_r);
        EXPECT_NEAR(hk.btdf(ti, to, phi), expected_t, 5e-3 * expected_t);
        EXPECT_NEAR(lambert.brdf_subsurface(ti, to, phi), diffuse, 1e-12);
        EXPECT_EQ(lambert.btdf(ti, to, phi), 0.0);
      }
    }
  }
  EXPECT_EQ(parse_subsurface_model("hk"), SubsurfaceModel::HanrahanKrueger);
  EXPECT_EQ(parse_subsurface_model("lambert"), SubsurfaceModel::Lambert);
  EXPECT_EQ(parse_subsurface_model("stam"), SubsurfaceModel::Stam);
  EXPECT_FALSE(parse_subsurface_model("phong").has_value());
}

}  // namespace
}  // namespace skinlayer
