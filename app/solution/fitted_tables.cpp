#include "app/solution/fitted_tables.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/solution/principled_fit_document.h"
#include "core/conventions.h"
#include "core/series/brdf_projection.h"
#include "core/targets/cycles_principled.h"
#include "core/targets/openpbr_surface.h"

namespace skinlayer {
namespace {

// The shader's f cos(theta_i) as a BRDF on the tables' angles (light at azimuth 0, view at phi); the light held just
// above the horizon at the grid's last angle, where f cos(theta_i) / cos(theta_i) is 0 / 0.
RgbBrdf as_brdf(const FittedBrdfCosine& cosine_weighted) {
  return [cosine_weighted](double theta_i, double theta_o, double phi) {
    const double ti = std::min(theta_i, degrees_to_radians(89.9));
    return Eigen::Array3d(cosine_weighted(direction_from_angles(ti, 0.0), direction_from_angles(theta_o, phi)) /
                          std::cos(ti));
  };
}

std::string summary(const char* name, const FitErrors& errors) {
  char text[160];
  std::snprintf(text, sizeof text, "%s fit: lobe RMS %.1f / %.1f / %.1f%%, albedo worst %.1f / %.1f / %.1f%%", name,
                100 * errors.lobe_rms(0), 100 * errors.lobe_rms(1), 100 * errors.lobe_rms(2),
                100 * errors.albedo_worst(0), 100 * errors.albedo_worst(1), 100 * errors.albedo_worst(2));
  return text;
}

}  // namespace

FittedTables fitted_tables(const ColorTables& shown, ShaderTarget target, const ParallelFor& parallel_for) {
  const MaterialDocument document = material_document(shown.material);
  RgbBrdf brdf;
  Rgb reflected;  // the fit's albedo at the shown tables' angle
  FittedTables result;
  if (target == ShaderTarget::Principled) {
    const DocumentFit<CyclesPrincipledFit> fit = fit_cycles_principled(document, parallel_for);
    brdf = as_brdf(fitted_brdf_cosine(fit.fit));
    reflected = CyclesPrincipled(fit.fit.parameters).albedo(std::cos(shown.albedo_theta_i));
    result.summary = summary("Principled", fit.fit.errors);
  } else {
    const DocumentFit<OpenPbrFit> fit = fit_openpbr(document, parallel_for);
    brdf = as_brdf(fitted_brdf_cosine(fit.fit));
    reflected = OpenPbrSurface(fit.fit.parameters).albedo(std::cos(shown.albedo_theta_i));
    result.summary = summary("OpenPBR", fit.fit.errors);
  }
  const LayerTables& grid = shown.channels[0];
  ColorTables& tables = result.tables;
  tables.material = shown.material;
  tables.material.layer.eta = 1.0;  // no surface term: the fitted BRDF holds it
  tables.channels = project_brdf(brdf, grid.grid_size(), std::max(grid.modes(), 32), parallel_for);
  tables.albedo_theta_i = shown.albedo_theta_i;
  for (int c = 0; c < 3; ++c) {
    DirectionalAlbedo& a = tables.albedo[static_cast<std::size_t>(c)];
    a.theta_i = shown.albedo_theta_i;
    a.reflectance_surface = 0.0;
    a.reflectance_subsurface = reflected(c);
    a.transmittance = 0.0;
    a.absorptance = 1.0 - reflected(c);
    a.interface_loss = 0.0;
  }
  return result;
}

}  // namespace skinlayer
