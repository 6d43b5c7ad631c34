// Directional-hemispherical reflectance and transmittance of one rough dielectric interface.
#pragma once

#include <span>
#include <vector>

#include "core/interfaces/microfacet.h"

namespace skinlayer {

struct InterfaceAlbedo {
  double reflectance;    // int f_r |wo.n| d omega_o
  double transmittance;  // int f_t |wo.n| d omega_o  (energy; f_t is a radiance BTDF)
  double loss() const { return 1.0 - reflectance - transmittance; }  // what Smith shadowing-masking removes
};

// Integrates over microfacet normals in slope space, where D(h) cos(alpha) d omega_h is the Gaussian slope density
// exp(-(p^2+q^2)/sigma^2)/(pi sigma^2) dp dq. Changing variables from outgoing direction to h turns both integrands
// into  F-or-(1-F) * G2(wi, wo) * |wi.h| / (|wi.n| h.n)  (Walter et al. 2007, eqs. 14 and 17; G2 the interface's
// masking-shadowing, smith_masking.h, G1(wi) G1(wo) under MicrofacetModel::Single). That integrand is
// smooth except on conics in slope space: the visibility cut-offs (wi.h = 0; the reflected or the refracted
// direction on the horizon) and, for light on the denser side, the square-root edge of 1 - F at total internal
// reflection. Rows of constant cross-slope are integrated piecewise between those curves' intersections, found in
// closed form, with Gauss-Legendre on each piece (a u^2 map near the square-root edges); absolute error < 1e-6 under
// MicrofacetModel::Single, < 3e-5 under Multiple, whose integrals only split its light between two lobes and take
// smaller rules (tests/core/interfaces/interface_albedo_test.cpp, against adaptive Gauss-Kronrod over outgoing
// directions). At eta = 1 the interface is absent: reflectance 0, transmittance 1.
InterfaceAlbedo single_scattering_albedo(const RoughDielectric& interface, const Vec3& wi);

// The same for many incident directions at once, sharing the quadrature rules and the slope grid (what the solver
// needs per node and per table direction).
std::vector<InterfaceAlbedo> single_scattering_albedo(const RoughDielectric& interface, std::span<const Vec3> wi);

// The interface's albedos. Under MicrofacetModel::Single, the single-scattering ones above: what Smith shadowing
// removes is lost. Under Multiple, those plus the light scattered more than once on the microsurface, which is all
// that single scattering leaves, l = 1 - R - T, split between reflection and transmission by the multiply scattered
// lobe's transmitted share s (core/interfaces/multiple_scattering.h): R + l (1 - s) and T + l s, so R + T = 1 (where
// the quadrature carries R + T of single scattering past 1, both are scaled back to a sum of 1 and l = 0).
InterfaceAlbedo interface_albedo(const RoughDielectric& interface, const Vec3& wi);
std::vector<InterfaceAlbedo> interface_albedo(const RoughDielectric& interface, std::span<const Vec3> wi);

// The same albedos in their two parts: the single scattering's, and the multiply scattered light's, {l (1 - s), l s}
// ({0, 0} under MicrofacetModel::Single). The solver matches each part of its interface operators to its own.
struct InterfaceAlbedoParts {
  InterfaceAlbedo single;
  InterfaceAlbedo multiple;
  InterfaceAlbedo total() const {
    return {single.reflectance + multiple.reflectance, single.transmittance + multiple.transmittance};
  }
};
// `lobe`, when given, is the interface's (built once by a caller that needs it for its kernels too); else one is built.
class MultipleScatteringLobe;
std::vector<InterfaceAlbedoParts> interface_albedo_parts(const RoughDielectric& interface, std::span<const Vec3> wi,
                                                         const MultipleScatteringLobe* lobe = nullptr);
// Each direction's whole albedos, part by part summed.
std::vector<InterfaceAlbedo> totals(std::span<const InterfaceAlbedoParts> parts);

}  // namespace skinlayer
