#include "core/models/subsurface_model.h"

#include <cmath>
#include <string>
#include <vector>

#include "core/conventions.h"
#include "core/models/hanrahan_krueger.h"
#include "core/models/lambert_model.h"
#include "core/series/fourier.h"

namespace skinlayer {
namespace {

constexpr int kDefaultTableSize = 48;

int table_size(const SolveOptions& options) { return options.table_size > 0 ? options.table_size : kDefaultTableSize; }

LayerTables lambert_tables(const Material& material, const SolveOptions& options) {
  const int k = table_size(options);
  const std::vector<double> reflection(static_cast<std::size_t>(k) * k, lambert_model_for(material).brdf_subsurface());
  return LayerTables(k, 1, reflection, std::vector<double>(reflection.size(), 0.0));
}

// Samples f(theta_i, theta_o, phi) on the grid and projects each (theta_i, theta_o) pair onto cos(m phi), keeping
// modes until two in a row fall below the tolerance of mode 0's peak (both tables).
LayerTables hanrahan_krueger_tables(const Material& material, const SolveOptions& options) {
  validate(material);
  const int k = table_size(options);
  const int max_modes = options.max_modes > 0 ? options.max_modes : 128;
  const CosineProjector projector(max_modes, 2 * max_modes + 1);
  const std::size_t plane = static_cast<std::size_t>(k) * k;
  Eigen::MatrixXd reflection_samples(projector.samples(), static_cast<Eigen::Index>(plane));
  Eigen::MatrixXd transmission_samples(projector.samples(), static_cast<Eigen::Index>(plane));
  for (int i = 0; i < k; ++i) {
    const double theta_i = LayerTables::grid_angle(i, k);
    for (int o = 0; o < k; ++o) {
      const double theta_o = LayerTables::grid_angle(o, k);
      const Eigen::Index column = static_cast<Eigen::Index>(i) * k + o;
      for (int s = 0; s < projector.samples(); ++s) {
        const double phi = projector.angle(s);
        reflection_samples(s, column) = hanrahan_krueger_brdf_subsurface(material, theta_i, theta_o, phi);
        transmission_samples(s, column) = hanrahan_krueger_btdf(material, theta_i, theta_o, phi);
      }
    }
  }
  const Eigen::MatrixXd reflection = projector.project(reflection_samples);
  const Eigen::MatrixXd transmission = projector.project(transmission_samples);
  const double peak_r = reflection.row(0).cwiseAbs().maxCoeff();
  const double peak_t = transmission.row(0).cwiseAbs().maxCoeff();
  int modes = 1, quiet = 0;
  for (int m = 1; m < max_modes && quiet < 2; ++m) {
    const bool small = reflection.row(m).cwiseAbs().maxCoeff() <= options.fourier_tolerance * peak_r &&
                       transmission.row(m).cwiseAbs().maxCoeff() <= options.fourier_tolerance * peak_t;
    quiet = small ? quiet + 1 : 0;
    modes = m + 1;
  }
  std::vector<double> r(plane * modes), t(plane * modes);
  for (int m = 0; m < modes; ++m) {
    for (std::size_t c = 0; c < plane; ++c) {
      r[m * plane + c] = reflection(m, static_cast<Eigen::Index>(c));
      t[m * plane + c] = transmission(m, static_cast<Eigen::Index>(c));
    }
  }
  return LayerTables(k, modes, std::move(r), std::move(t));
}

}  // namespace

std::string_view subsurface_model_name(SubsurfaceModel model) {
  switch (model) {
    case SubsurfaceModel::Stam: return "stam";
    case SubsurfaceModel::Lambert: return "lambert";
    case SubsurfaceModel::HanrahanKrueger: return "hk";
  }
  return "stam";
}

std::optional<SubsurfaceModel> parse_subsurface_model(std::string_view name) {
  for (const SubsurfaceModel model : {SubsurfaceModel::Stam, SubsurfaceModel::Lambert, SubsurfaceModel::HanrahanKrueger}) {
    if (name == subsurface_model_name(model)) return model;
  }
  return std::nullopt;
}

LayerTables solve_model(const Material& material, SubsurfaceModel model, const SolveOptions& options) {
  if (model != SubsurfaceModel::Stam && !material.below.empty()) {
    throw ParameterError("model = " + std::string(subsurface_model_name(model)) + " describes one layer; a stack of " +
                         std::to_string(material.layer_count()) + " layers takes model stam");
  }
  switch (model) {
    case SubsurfaceModel::Lambert: return lambert_tables(material, options);
    case SubsurfaceModel::HanrahanKrueger: return hanrahan_krueger_tables(material, options);
    case SubsurfaceModel::Stam: break;
  }
  return solve(material, options);
}

}  // namespace skinlayer
