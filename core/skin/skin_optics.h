// Per-wavelength optical properties of a two-layer skin from its biophysical parameters (skin_parameters.h), and
// the layered Material they make. Wavelengths in nm; coefficients in 1/mm.
//
// Absorption:
//   baseline (bloodless, melanin-free tissue; Jacques 1998, OMLC "Skin optics", in 1/mm):
//     mu_a,base = 0.0244 + 8.53 exp(-(lambda - 154) / 66.2);
//   melanin (the power laws of Donner & Jensen 2006 as implementations citing them write them; the paper's text was
//   not available to check them, and Jacques 2013 eq. 8's melanosome law, 51.9 (lambda/500)^-3 1/mm, is of the same
//   size: 52 against eumelanin's 68 at 500 nm), in 1/mm, lambda in nm:
//     mu_a,eu = 6.6e10 lambda^-3.33,   mu_a,pheo = 2.9e14 lambda^-4.75;
//   whole blood (Prahl's tabulated molar extinction epsilon in cm^-1/M, core/data/hemoglobin_prahl.csv, at
//   150 g/L of hemoglobin of 64,500 g/mol; Jacques 2013 eq. 6):
//     mu_a,blood = ln(10) epsilon 150 / 64500 / 10   (the /10 turns 1/cm into 1/mm),
//     with epsilon = S epsilon_HbO2 + (1 - S) epsilon_Hb;
//   epidermis: mu_a = Cm (beta mu_a,eu + (1 - beta) mu_a,pheo) + (1 - Cm) mu_a,base;
//   dermis:    mu_a = Ch mu_a,blood + (1 - Ch) mu_a,base.
// Reduced scattering (Jacques 2013 eq. 1, its Table 1 fits of Salomatina et al. 2006, a in 1/cm):
//   epidermis mu_s' = 6.87 (lambda / 500)^-1.161,  dermis mu_s' = 4.53 (lambda / 500)^-1.292   (1/mm),
//   times the `scattering` scale; mu_s = mu_s' / (1 - g) with g = kSkinAnisotropy.
// Each layer: Omega = mu_s / (mu_s + mu_a); the epidermis has tau = (mu_s + mu_a) d, the dermis is semi-infinite.
#pragma once

#include <span>
#include <vector>

#include "core/material.h"
#include "core/skin/skin_parameters.h"

namespace skinlayer {

// The Henyey-Greenstein g of both layers: forward scattering in the 0.8-0.9 that skin models use (Jacques 2013
// reports goniometric g > 0.9 in the visible; a lower g costs fewer Fourier modes and changes little once mu_s'
// is fixed).
inline constexpr double kSkinAnisotropy = 0.8;

struct LayerOptics {
  double absorption = 0.0;                                                            // mu_a, 1/mm
  double reduced_scattering = 0.0;                                                    // mu_s', 1/mm
  double scattering() const { return reduced_scattering / (1.0 - kSkinAnisotropy); }  // mu_s, 1/mm
  double extinction() const { return scattering() + absorption; }                     // mu_t, 1/mm
  double albedo() const { return scattering() / extinction(); }                       // Omega
};

double baseline_absorption(double wavelength_nm);     // mu_a,base, 1/mm
double eumelanin_absorption(double wavelength_nm);    // mu_a,eu, 1/mm
double pheomelanin_absorption(double wavelength_nm);  // mu_a,pheo, 1/mm
// mu_a of whole blood at oxygen saturation S, 1/mm (tabulated 250-1000 nm; linear between the 2 nm rows).
double blood_absorption(double wavelength_nm, double oxygenation);

LayerOptics epidermis_optics(const SkinParameters& skin, double wavelength_nm);
LayerOptics dermis_optics(const SkinParameters& skin, double wavelength_nm);

// The skin at one wavelength as a layered Material: the top interface (sigma, eta), its microfacet model and the
// ordinates from `interfaces`; the epidermis as the first layer and the dermis semi-infinite under it, with no
// interface between them, both with g = kSkinAnisotropy and their extinction mu_t (so the epidermis is
// skin.epidermis mm thick).
Material skin_material(const SkinParameters& skin, double wavelength_nm, const Material& interfaces = {});

// The wavelengths from..to (inclusive) in steps of step nm.
std::vector<double> wavelength_grid(double from_nm, double to_nm, double step_nm);

}  // namespace skinlayer
