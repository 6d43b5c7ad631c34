// Solves the default material with the installed library and prints its directional albedo at normal incidence
// and one BRDF value, each with 17 digits, for the install test to compare with the installed command line.
#include <cstdio>
#include <vector>

#include "core/conventions.h"
#include "core/material.h"
#include "core/solver.h"

int main() {
  const skinlayer::Material material;  // skinlayer's defaults, as `skinlayer albedo` with no flags
  const std::vector<double> theta_i = {0.0};
  const skinlayer::DirectionalAlbedo albedo = skinlayer::directional_albedo(material, theta_i).front();
  const skinlayer::LayerTables tables = skinlayer::solve(material);
  const double theta = skinlayer::degrees_to_radians(30.0), forward = skinlayer::degrees_to_radians(180.0);
  std::printf("reflectance %.17g\ntransmittance %.17g\nbrdf_subsurface %.17g\n", albedo.reflectance(),
              albedo.transmittance, tables.brdf_subsurface(theta, theta, forward));
  return 0;
}
