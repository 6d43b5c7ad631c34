// The light that enters through a rough top, reflects once off a rough bottom and leaves through the top without
// being scattered by the medium: t21 e^{-tau/mu} R23 e^{-tau/mu'} t12, Stam 2001's boundary operators applied to the
// unscattered beam. The discrete ordinates carry it as the node image
//   B^m = T_exit^m diag(e^{-tau/mu_j}) R23^m diag(e^{-tau/mu_j}) T_source^m        (per Fourier mode m, K x K),
// a node quadrature of a 4-D integral whose inner factors are the narrow refraction lobes (about sigma (1 - 1/eta)
// wide inside). Where the light leaves near the critical angle that quadrature ripples by 1.5-3% from one N to the
// next (the forward-grazing mirror of thin or weakly scattering layers), more than the rest of the field does, so
// the solver replaces it by the same image on four times the ordinates the top's refracted lobe needs (96 to 256)
// wherever it matters.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "core/interfaces/layer_interfaces.h"

namespace skinlayer {

// B^m on the kernels' ordinates (InterfaceKernels of a closed top over a rough bottom, with exit rows), in the
// solver's propagation convention (the caller applies the graphics azimuth parity). `attenuation` is e^{-tau/mu_j}
// on those ordinates (slab_attenuation, core/solve/boundary_solve.h), computed once for every mode. Dimensionless, like
// the kernels' products.
Eigen::MatrixXd bottom_bounce_image(const InterfaceKernels& kernels, const Eigen::VectorXd& attenuation, int m);

// Whether the node image matters at N: somewhere the mode-0 subsurface BRDF table counts (above 1e-3 of its peak),
// the image's mode 0 reaches `fraction` of it. Measured (mode-0 share -> worst pointwise error at N without the
// finer image): 0.006 -> 0.09% (the paper's default), 0.075 -> 0.4%, 0.15 -> 0.5%, 0.56 -> 1.5%, 0.89-1.01 -> 1.5-3.2%;
// 0.73 -> 0.5% at sigma 0.05, where the finer image is not needed but harmless. `image_mode0` is B^0;
// `reflection_mode0` holds the K x K table R^0(o, i) of each albedo.
bool bottom_bounce_matters(const Eigen::MatrixXd& image_mode0, std::span<const Eigen::MatrixXd> reflection_mode0,
                           double fraction = 0.4);

// The finer ordinate count for the image: four times the base need of the top's refracted lobe, 1.75 ordinates per
// lobe width sigma (1 - 1/eta) (core/solver.cpp's rule away from index matching, where it asks up to 6), but at
// least 96 (the ripple is worst where the
// light leaves near the critical angle, whatever sigma: at sigma 0.5, 52 ordinates left 1.0%, 96 left 0.37%), a
// multiple of 4, at most 256, and at least the solve's own N (equal to it: no correction is needed).
int bottom_bounce_ordinates(int ordinates, const RoughDielectric& top);

}  // namespace skinlayer
