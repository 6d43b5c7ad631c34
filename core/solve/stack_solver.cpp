#include "core/solve/stack_solver.h"

#include <cmath>

#include "core/conventions.h"
#include "core/medium/slab_eigen.h"
#include "core/solve/boundary_solve.h"
#include "core/solve/solve_cache.h"

namespace skinlayer {
namespace {

Eigen::VectorXd cosines(std::span<const double> mu) {
  return Eigen::Map<const Eigen::VectorXd>(mu.data(), static_cast<Eigen::Index>(mu.size()));
}

// 2 pi mu_j a_j: node radiance of mode 0 to flux.
Eigen::RowVectorXd flux_weights(const QuadratureRule& q) {
  Eigen::RowVectorXd w(q.size());
  for (Eigen::Index j = 0; j < q.size(); ++j) w(j) = 2.0 * kPi * q.nodes[j] * q.weights[j];
  return w;
}

}  // namespace

StackSolver::StackSolver(const Material& material, const Resolution& resolution,
                         std::shared_ptr<const InterfaceKernels> kernels, UnscatteredPath exact_path,
                         bool exact_surface_multiple, SolveCache* cache, const ParallelFor& parallel_for,
                         const CancelCheck& cancelled)
    : kernels_(std::move(kernels)), layers_(stack_layers(material)), bottom_(material.bottom) {
  const LayerGeometry& geometry = kernels_->geometry;
  const QuadratureRule& q = kernels_->quadrature;
  const std::vector<double>& mu_in = kernels_->mu_in;
  const std::vector<double>& mu_out = kernels_->mu_out;
  want_exit_ = !mu_out.empty();
  exact_path_ = want_exit_ ? exact_path : UnscatteredPath::None;
  exact_surface_multiple_ = exact_surface_multiple;
  exterior_ = want_exit_ && (geometry.top_open || geometry.base == LayerBase::Open);
  const std::size_t count = layers_.size();

  // The beam: unit amplitude at the open top, attenuated through each slab, gone at the first rough interface.
  Eigen::VectorXd amplitude =
      geometry.top_open ? Eigen::VectorXd::Ones(static_cast<Eigen::Index>(mu_in.size())) : Eigen::VectorXd();
  for (std::size_t i = 0; i < count; ++i) {
    const StackedLayer& layer = layers_[i];
    const bool rough_above = layer.interface && layer.interface->eta != 1.0;
    faces_.push_back(nullptr);
    if (i > 0 && rough_above) {
      InternalInterfaceNeeds needs;
      needs.up_rows = want_exit_ && geometry.top_open;
      needs.down_rows = want_exit_ && geometry.base == LayerBase::Open;
      needs.beam = amplitude.size() != 0;
      const InternalInterfaceKey key{{layer.interface->eta, layer.interface->sigma, material.microfacet},
                                     resolution.ordinates,
                                     resolution.interface_modes,
                                     resolution.interface_azimuths,
                                     mu_in,
                                     mu_out,
                                     needs.up_rows,
                                     needs.down_rows,
                                     needs.beam};
      const auto build = [&] {
        return internal_interface_kernels(key.interface, q, key.modes, key.azimuths, key.mu_in, key.mu_out, needs,
                                          parallel_for, cancelled);
      };
      faces_[i - 1] = cache ? cache->internal_interface_kernels(key, build)
                            : std::make_shared<const InternalInterfaceKernels>(build());
      amplitude.resize(0);
    }
    beam_amplitude_.push_back(amplitude);
    beam_attenuation_.push_back(slab_attenuation(mu_in, layer.tau));
    if (amplitude.size() != 0) amplitude = amplitude.cwiseProduct(beam_attenuation_.back());
  }
  faces_.pop_back();  // n - 1 faces
  if (std::isinf(layers_.back().tau)) amplitude.resize(0);
  beam_at_bottom_ = amplitude;

  // The exact path's rough interfaces (as UnscatteredLight(material) finds them) and the depth between them.
  if (exact_path_ != UnscatteredPath::None) {
    std::vector<std::pair<int, double>> crossings;  // position, depth above
    if (!geometry.top_open) crossings.emplace_back(kTop, 0.0);
    double depth = layers_.front().tau;
    for (std::size_t i = 1; i < count; ++i) {
      if (faces_[i - 1] != nullptr) crossings.emplace_back(static_cast<int>(i - 1), depth);
      depth += layers_[i].tau;
    }
    if (geometry.base == LayerBase::Rough) crossings.emplace_back(kBottom, depth);
    exact_first_ = crossings.front().first;
    if (crossings.size() == 2) {
      exact_second_ = crossings[1].first;
      exact_between_ = slab_attenuation(q.nodes, crossings[1].second - crossings[0].second);
    }
  }

  for (std::size_t i = 0; i < count; ++i) {
    phase_.push_back(cached_phase_kernels(cache, layers_[i].g, q, resolution.max_modes, resolution.phase_azimuths,
                                          mu_in, mu_out, beam_amplitude_[i].size() != 0, exterior_, cancelled));
  }
}

Eigen::MatrixXd StackSolver::exact_image_at_second(int m) const {
  if (exact_first_ == kTop) {
    return exact_between_.asDiagonal() * kernels_->t_source.single_scattering(m);
  }
  const std::size_t face = static_cast<std::size_t>(exact_first_);
  const Eigen::VectorXd arriving = beam_amplitude_[face].cwiseProduct(beam_attenuation_[face]);
  return exact_between_.asDiagonal() * faces_[face]->beam_transmit.single_scattering(m) * arriving.asDiagonal();
}

ExitScattering StackSolver::exit_rows(int m, std::size_t slab, double albedo, bool upward) const {
  const QuadratureRule& q = kernels_->quadrature;
  const Eigen::Map<const Eigen::VectorXd> a(q.weights.data(), q.size());
  const double solved_albedo = std::min(albedo, kMaxSolvedAlbedo);
  const double scattering = solved_albedo * fourier_azimuth_weight(m);
  const PhaseKernels& phase = *phase_[slab];
  ExitScattering exit{kernels_->mu_out,
                      scattering * phase.same_rows[m] * a.asDiagonal(),
                      scattering * phase.opposite_rows[m] * a.asDiagonal(),
                      {}};
  const Eigen::VectorXd& amplitude = beam_amplitude_[slab];
  if (amplitude.size() != 0) {
    const Eigen::VectorXd flux = cosines(kernels_->mu_in).cwiseInverse().cwiseProduct(amplitude);
    exit.beam_row = solved_albedo * (upward ? phase.beam_rows_up[m] : phase.beam_rows_down[m]) * flux.asDiagonal();
  }
  return exit;
}

StackSolver::ModeResult StackSolver::solve_mode(int m, std::span<const double> albedos) const {
  const LayerGeometry& geometry = kernels_->geometry;
  const QuadratureRule& q = kernels_->quadrature;
  const std::size_t count = layers_.size();
  const Eigen::Index n = q.size();
  const Eigen::Index count_in = static_cast<Eigen::Index>(kernels_->mu_in.size());
  const Eigen::Index count_out = static_cast<Eigen::Index>(kernels_->mu_out.size());
  const bool lambert_mode = geometry.base == LayerBase::Lambert && m == 0;
  const double lambert = bottom_.lambert_albedo;
  const bool infinite = std::isinf(layers_.back().tau);

  std::vector<SlabEigenSolution> eigen(count);
  std::vector<BeamParticular> beams(count);
  std::vector<BoundaryProblem> problems(count);
  for (std::size_t i = 0; i < count; ++i) {
    const PhaseKernels& phase = *phase_[i];
    eigen[i] = slab_mode_eigen(q.nodes, q.weights, phase.phase.same[m], phase.phase.opposite[m], m, albedos[i],
                               layers_[i].tau);
    problems[i].eigen = &eigen[i];
    problems[i].tau = layers_[i].tau;
    if (beam_amplitude_[i].size() != 0) {
      beams[i] = beam_particular(phase, q, m, std::min(albedos[i], kMaxSolvedAlbedo), kernels_->mu_in);
      beams[i].up *= beam_amplitude_[i].asDiagonal();
      beams[i].down *= beam_amplitude_[i].asDiagonal();
      problems[i].beam = &beams[i];
    }
  }
  BoundaryProblem& top = problems.front();
  if (!geometry.top_open) {
    top.reflect_top = kernels_->r_top[m];
    top.source_top = kernels_->t_source.kernel[m];
  }
  BoundaryProblem& last = problems.back();
  const bool beam_at_bottom = beam_at_bottom_.size() != 0;
  if (geometry.base == LayerBase::Rough) {
    last.reflect_bottom = kernels_->r_bottom[m];
    if (beam_at_bottom) last.source_bottom = kernels_->s_bottom_beam[m] * beam_at_bottom_.asDiagonal();
  } else if (lambert_mode) {
    last.reflect_bottom = lambert_reflection(q, lambert);
    if (beam_at_bottom) last.source_bottom = (lambert * kInvPi) * beam_at_bottom_.transpose().replicate(n, 1);
  }
  std::vector<FaceCoupling> couplings(count - 1);
  for (std::size_t f = 0; f + 1 < count; ++f) {
    if (!internal_face(f)) continue;
    const InternalInterfaceKernels& face = *faces_[f];
    FaceCoupling& c = couplings[f];
    c.reflect_above = face.reflect_above[m];
    c.reflect_below = face.reflect_below[m];
    c.transmit_down = face.transmit_down[m];
    c.transmit_up = face.transmit_up[m];
    if (beam_amplitude_[f].size() != 0) {
      const Eigen::VectorXd arriving = beam_amplitude_[f].cwiseProduct(beam_attenuation_[f]);
      c.source_up = face.beam_reflect[m] * arriving.asDiagonal();
      c.source_down = face.beam_transmit.kernel[m] * arriving.asDiagonal();
    }
  }

  ModeResult result;
  result.field = solve_stack_boundary(problems, couplings, static_cast<int>(count_in));
  const StackField& field = result.field;
  if (!want_exit_) return result;

  // Out through the top.
  if (!geometry.top_open) {
    result.reflection = kernels_->t_exit.kernel[m] * field.slabs.front().up_top;
    // The top's multiply scattered reflection of the incident light, unless UnscatteredLight::brdf holds it.
    const FourierKernel& surface = kernels_->r_surface_multiple;
    if (!exact_surface_multiple_ && m < static_cast<int>(surface.size())) {
      result.reflection += surface[static_cast<std::size_t>(m)];
    }
  } else {
    // The upward radiance at each slab's bottom face along the exits, from the bottom up.
    Eigen::MatrixXd below;  // at the current slab's bottom
    if (!infinite && geometry.base == LayerBase::Rough) {
      below = kernels_->r_bottom_rows[m] * field.slabs.back().down_bottom;
      const Eigen::MatrixXd* beam_rows =
          beam_at_bottom ? kernels_->r_bottom_beam_rows.carried_by_tables(m, exact_path_ == UnscatteredPath::BottomOnly)
                         : nullptr;
      if (beam_rows != nullptr) below += *beam_rows * beam_at_bottom_.asDiagonal();
    } else if (!infinite && lambert_mode) {
      Eigen::RowVectorXd flux = flux_weights(q) * field.slabs.back().down_bottom;
      if (beam_at_bottom) flux += beam_at_bottom_.transpose();
      below = (lambert * kInvPi) * flux.replicate(count_out, 1);
    }
    for (std::size_t i = count; i-- > 0;) {
      const Eigen::MatrixXd at_top =
          upward_radiance_at_top(problems[i], field.slabs[i], exit_rows(m, i, albedos[i], true), below);
      if (i == 0) {
        result.reflection = at_top;
        break;
      }
      if (!internal_face(i - 1)) {
        below = at_top;
        continue;
      }
      const InternalInterfaceKernels& face = *faces_[i - 1];
      below = face.reflect_above_rows[m] * field.slabs[i - 1].down_bottom +
              face.transmit_up_rows[m] * field.slabs[i].up_top;
      // The beam's reflection off this interface: UnscatteredLight::brdf when it is the exact path's.
      const bool exact = exact_path_ == UnscatteredPath::BottomOnly && exact_first_ == static_cast<int>(i - 1);
      const Eigen::MatrixXd* rows =
          beam_amplitude_[i - 1].size() != 0 ? face.beam_reflect_rows.carried_by_tables(m, exact) : nullptr;
      if (rows != nullptr) {
        below += *rows * beam_amplitude_[i - 1].cwiseProduct(beam_attenuation_[i - 1]).asDiagonal();
      }
    }
  }

  // Out through the bottom.
  if (infinite || geometry.base == LayerBase::Lambert) {
    result.transmission = Eigen::MatrixXd::Zero(count_out, count_in);
  } else if (geometry.base == LayerBase::Rough) {
    // As for one layer: the light that crossed the interfaces unscattered is on the nodes as the first-pass part
    // of the bottom's downward field; it is UnscatteredLight::btdf when evaluated exactly.
    const InterfaceKernel& exit = kernels_->t_bottom_exit;
    if (exact_path_ != UnscatteredPath::TopThenBottom || exact_second_ != kBottom) {
      result.transmission = exit.kernel[m] * field.slabs.back().down_bottom;
    } else if (exit.has_multiple(m)) {
      result.transmission =
          exit.kernel[m] * field.slabs.back().down_bottom - exit.single_scattering(m) * exact_image_at_second(m);
    } else {
      result.transmission = exit.kernel[m] * (field.slabs.back().down_bottom - exact_image_at_second(m));
    }
    const Eigen::MatrixXd* beam =
        beam_at_bottom ? kernels_->t_bottom_beam.carried_by_tables(m, exact_path_ == UnscatteredPath::BottomOnly)
                       : nullptr;
    if (beam != nullptr) result.transmission += *beam * beam_at_bottom_.asDiagonal();
  } else {
    // The downward radiance at each slab's top face along the exits, from the top down.
    Eigen::MatrixXd above;
    if (!geometry.top_open) {
      above = kernels_->r_top_rows[m] * field.slabs.front().up_top;
      const Eigen::MatrixXd* source =
          kernels_->t_source_exterior.carried_by_tables(m, exact_path_ == UnscatteredPath::TopOnly);
      if (source != nullptr) above += *source;
    }
    for (std::size_t i = 0; i < count; ++i) {
      const Eigen::MatrixXd at_bottom =
          downward_radiance_at_bottom(problems[i], field.slabs[i], exit_rows(m, i, albedos[i], false), above);
      if (i + 1 == count) {
        result.transmission = at_bottom;
        break;
      }
      if (!internal_face(i)) {
        above = at_bottom;
        continue;
      }
      const InternalInterfaceKernels& face = *faces_[i];
      // The first pass of the exact path through this interface, or the beam straight through it, is
      // UnscatteredLight::btdf when evaluated exactly.
      const int position = static_cast<int>(i);
      Eigen::MatrixXd arriving = field.slabs[i].down_bottom;
      const bool second = exact_path_ == UnscatteredPath::TopThenBottom && exact_second_ == position;
      const bool multiple = face.transmit_down_rows.has_multiple(m);
      if (second && !multiple) arriving -= exact_image_at_second(m);
      above = face.reflect_below_rows[m] * field.slabs[i + 1].up_top + face.transmit_down_rows.kernel[m] * arriving;
      if (second && multiple) {
        above -= face.transmit_down_rows.single_scattering(m) * exact_image_at_second(m);
      }
      const bool exact = exact_path_ == UnscatteredPath::BottomOnly && exact_first_ == position;
      const Eigen::MatrixXd* rows =
          beam_amplitude_[i].size() != 0 ? face.beam_transmit_rows.carried_by_tables(m, exact) : nullptr;
      if (rows != nullptr) {
        above += *rows * beam_amplitude_[i].cwiseProduct(beam_attenuation_[i]).asDiagonal();
      }
    }
  }
  const double parity = azimuth_parity(m);
  result.reflection *= parity;
  result.transmission *= parity;
  return result;
}

std::vector<DirectionalAlbedo> StackSolver::directional_albedo(const ModeResult& mode0) const {
  const LayerGeometry& geometry = kernels_->geometry;
  const QuadratureRule& q = kernels_->quadrature;
  const StackField& field = mode0.field;
  const std::size_t count = layers_.size();
  const Eigen::RowVectorXd w = flux_weights(q);
  const auto along = [&](const std::vector<InterfaceAlbedo>& albedos, auto part) {
    Eigen::RowVectorXd row(q.size());
    for (Eigen::Index j = 0; j < q.size(); ++j) row(j) = w(j) * part(albedos[static_cast<std::size_t>(j)]);
    return row;
  };
  const auto transmitted = [](const InterfaceAlbedo& a) { return a.transmittance; };
  const auto lost = [](const InterfaceAlbedo& a) { return a.loss(); };

  // The interfaces' albedos for the incident light, which the kernels were matched to.
  const std::vector<InterfaceAlbedoParts>& entries = kernels_->top_outside;
  const bool beam_at_bottom = beam_at_bottom_.size() != 0;
  const std::vector<InterfaceAlbedo>& beam_exits = kernels_->bottom_beam_albedo;
  const Eigen::RowVectorXd top_out = along(kernels_->top_inside, transmitted);
  const Eigen::RowVectorXd top_lost = along(kernels_->top_inside, lost);
  const Eigen::RowVectorXd bottom_out = along(kernels_->bottom_inside, transmitted);
  const Eigen::RowVectorXd bottom_lost = along(kernels_->bottom_inside, lost);
  // Per interface between layers, the flux lost to shadowing from the down nodes above and the up nodes below.
  std::vector<std::pair<Eigen::RowVectorXd, Eigen::RowVectorXd>> face_lost(count - 1);
  for (std::size_t f = 0; f + 1 < count; ++f) {
    if (internal_face(f)) face_lost[f] = {along(faces_[f]->from_above, lost), along(faces_[f]->from_below, lost)};
  }

  std::vector<DirectionalAlbedo> rows;
  for (std::size_t k = 0; k < kernels_->mu_in.size(); ++k) {
    const Eigen::Index col = static_cast<Eigen::Index>(k);
    DirectionalAlbedo row{};
    row.theta_i = std::acos(kernels_->mu_in[k]);
    // The specular lobe is the single scattering's; the top's multiply scattered reflection is smooth and counted
    // with the light from below, as the tables carry it.
    row.reflectance_surface = entries[k].single.reflectance;
    row.interface_loss = entries[k].total().loss() + top_lost.dot(field.slabs.front().up_top.col(col));
    row.reflectance_subsurface = top_out.dot(field.slabs.front().up_top.col(col)) + entries[k].multiple.reflectance;
    const Eigen::VectorXd& down_last = field.slabs.back().down_bottom.col(col);
    const double direct = beam_at_bottom ? beam_at_bottom_(col) : 0.0;
    switch (geometry.base) {
      case LayerBase::Lambert:
        row.transmittance = 0.0;
        break;
      case LayerBase::Open:
        row.transmittance = w.dot(down_last) + direct;
        break;
      case LayerBase::Rough:
        row.transmittance = bottom_out.dot(down_last) + (beam_at_bottom ? direct * beam_exits[k].transmittance : 0.0);
        row.interface_loss += bottom_lost.dot(down_last) + (beam_at_bottom ? direct * beam_exits[k].loss() : 0.0);
        break;
    }
    if (std::isinf(layers_.back().tau)) row.transmittance = 0.0;
    for (std::size_t f = 0; f + 1 < count; ++f) {
      if (!internal_face(f)) continue;
      row.interface_loss += face_lost[f].first.dot(field.slabs[f].down_bottom.col(col)) +
                            face_lost[f].second.dot(field.slabs[f + 1].up_top.col(col));
      if (beam_amplitude_[f].size() != 0) {
        row.interface_loss += beam_amplitude_[f](col) * beam_attenuation_[f](col) * faces_[f]->beam_albedo[k].loss();
      }
    }
    // Each slab absorbs the net flux into its top face less the net flux out of its bottom face, the beam's
    // irradiance included. A single layer's is absorptance less the interfaces' share: not listed apart.
    for (std::size_t i = 0; count > 1 && i < count; ++i) {
      const NodeField& slab = field.slabs[i];
      const double beam_in = beam_amplitude_[i].size() != 0 ? beam_amplitude_[i](col) : 0.0;
      const double beam_out = beam_in * beam_attenuation_[i](col);
      const double net_top = w.dot(field.down_top[i].col(col)) + beam_in - w.dot(slab.up_top.col(col));
      const double net_bottom = w.dot(slab.down_bottom.col(col)) + beam_out - w.dot(field.up_bottom[i].col(col));
      row.layer_absorptance.push_back(net_top - net_bottom);
    }
    row.absorptance = 1.0 - row.reflectance() - row.transmittance;
    rows.push_back(row);
  }
  return rows;
}

}  // namespace skinlayer
