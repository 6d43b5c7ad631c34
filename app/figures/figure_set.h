// The figure series of Stam's results slides, as data: for each figure its file name, caption, the parameter it
// varies and one curve per value. Everywhere eta is 1.4 and the incident angle 45 degrees unless a figure varies
// them; the layer's bottom is air (the default) and the ordinates automatic.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/material.h"
#include "core/models/subsurface_model.h"
#include "core/skin/skin_parameters.h"

namespace skinlayer::figures {

// The parameters a figure sets, as the command line writes them (T, not tau, so that `skinlayer eval --T` gives
// back the same material).
struct LayerParams {
  double sigma = 0.5;
  double eta = 1.4;
  double transparency = 0.2;  // T
  double albedo = 1.0;        // Omega
  double g = 0.8;
  std::vector<StackedLayer> below;  // a stack's layers 2..n (the fields above are the first layer's)
  // The paper's figures are drawn with the paper's single-scattering interfaces (core/interfaces/microfacet_model.h).
  MicrofacetModel microfacet = MicrofacetModel::Single;

  Material material() const;  // bottom air, automatic ordinates
};

enum class FigureKind {
  SurfaceLobes,     // the top interface alone: brdf_surface (R) and the interface's microfacet BTDF into the layer (T)
  SubsurfaceLobes,  // the subsurface BRDF (R) and the layer's BTDF (T) of the chosen model
  ModelSpheres,     // lit spheres of Lambert, Hanrahan-Krueger and Stam side by side
  SkinSpectra,      // a spectral skin's directional-hemispherical reflectance against wavelength (skin_figures.h)
  SkinSpheres,      // lit spheres of spectral skins side by side, in linear sRGB under D65
  SkinProfiles,     // spectral skins' reflectance profiles R(r) per channel, log scale (skin_figures.h)
};

struct FigureCurve {
  std::string label;  // legend text
  std::string value;  // the varied parameter's value as written in the CSV (shortest form) or the model name
  LayerParams params;
  double theta_i_deg = 45.0;
  SubsurfaceModel model = SubsurfaceModel::Stam;
  std::array<double, 3> albedo_rgb = {1.0, 1.0, 1.0};  // ModelSpheres only: per-channel Omega
  std::optional<SkinParameters> skin = std::nullopt;  // SkinSpectra and SkinSpheres: the skin under params' top
};

struct FigureSpec {
  std::string name;       // file stem: NAME.png, NAME.csv
  std::string title;      // the picture's first line
  std::string subtitle;   // the picture's second line: the fixed parameters
  std::string caption;    // index.html's caption
  std::string parameter;  // the varied parameter's flag name (sigma, eta, theta_i, g, albedo, T, a skin key) or "model"
  FigureKind kind = FigureKind::SubsurfaceLobes;
  bool rescale_to_peak = false;  // each curve divided by its own peak before plotting
  int log_decades = 0;           // 0: linear radial scale; n: log10 over n decades (polar_plot.h)
  bool separate_scales = false;  // reflection and transmission each scaled to their own peak (polar_plot.h)
  double light_theta_deg = 45.0;  // sphere pictures: the light's angle from the view direction, from the left
  double sphere_radius_mm = 0.0;  // sphere pictures: > 0 spreads the subsurface light over a sphere of this radius
  std::vector<FigureCurve> curves;
};

std::vector<FigureSpec> figure_set();

}  // namespace skinlayer::figures
