#include "core/solve/stack_boundary.h"

#include <Eigen/LU>
#include <cmath>
#include <stdexcept>

namespace skinlayer {
namespace {

// A node radiance at one face of one slab as an affine function of the slab's constants:
//   value = minus c- + plus c+ + constant   (plus is empty for a semi-infinite slab).
struct Affine {
  Eigen::MatrixXd minus, plus, constant;
  Eigen::MatrixXd at(const Eigen::MatrixXd& c_minus, const Eigen::MatrixXd& c_plus) const {
    Eigen::MatrixXd value = minus * c_minus + constant;
    if (plus.size() != 0) value += plus * c_plus;
    return value;
  }
};

struct SlabFaces {
  Affine up_top, down_top, up_bottom, down_bottom;
  bool semi_infinite = false;
};

// From boundary_solve.h's general solution, with E = diag(e^{-k tau}) and the beam's e^{-tau/mu0} per column.
SlabFaces slab_faces(const BoundaryProblem& slab, Eigen::Index count) {
  const SlabEigenSolution& eigen = *slab.eigen;
  const Eigen::Index n = eigen.k.size();
  const Eigen::MatrixXd& gp = eigen.g_up;
  const Eigen::MatrixXd& gm = eigen.g_down;
  SlabFaces faces;
  faces.semi_infinite = std::isinf(slab.tau);
  Eigen::MatrixXd z_up = Eigen::MatrixXd::Zero(n, count), z_down = Eigen::MatrixXd::Zero(n, count);
  Eigen::VectorXd beam_attenuation = Eigen::VectorXd::Zero(count);
  if (slab.beam != nullptr) {
    z_up = slab.beam->up;
    z_down = slab.beam->down;
    for (Eigen::Index k = 0; k < count; ++k) {
      beam_attenuation(k) = faces.semi_infinite ? 0.0 : std::exp(-slab.tau / slab.beam->mu0(k));
    }
  }
  if (faces.semi_infinite) {
    faces.up_top = {gp, {}, z_up};
    faces.down_top = {gm, {}, z_down};
    return faces;
  }
  const Eigen::VectorXd e = (-eigen.k * slab.tau).array().exp();
  faces.up_top = {gp, gm * e.asDiagonal(), z_up};
  faces.down_top = {gm, gp * e.asDiagonal(), z_down};
  faces.up_bottom = {gp * e.asDiagonal(), gm, z_up * beam_attenuation.asDiagonal()};
  faces.down_bottom = {gm * e.asDiagonal(), gp, z_down * beam_attenuation.asDiagonal()};
  return faces;
}

}  // namespace

StackField solve_stack_boundary(std::span<const BoundaryProblem> slabs, std::span<const FaceCoupling> faces,
                                int incident_count) {
  if (slabs.empty() || faces.size() + 1 != slabs.size()) {
    throw std::invalid_argument("solve_stack_boundary: a stack of n slabs has n - 1 faces");
  }
  const Eigen::Index n = slabs.front().eigen->k.size();
  const Eigen::Index count = incident_count;
  const std::size_t layers = slabs.size();
  if (layers == 1) {
    // One slab: the same conditions without faces, which boundary_solve.h solves in its own, smaller system.
    StackField field;
    field.slabs.push_back(solve_boundary(slabs.front(), incident_count));
    return field;
  }
  std::vector<SlabFaces> values;
  std::vector<Eigen::Index> column;  // each slab's first unknown
  Eigen::Index unknowns = 0;
  for (std::size_t i = 0; i < layers; ++i) {
    if (std::isinf(slabs[i].tau) && i + 1 != layers) {
      throw std::invalid_argument("solve_stack_boundary: only the last slab may be semi-infinite");
    }
    values.push_back(slab_faces(slabs[i], count));
    column.push_back(unknowns);
    unknowns += values.back().semi_infinite ? n : 2 * n;
  }

  Eigen::MatrixXd system = Eigen::MatrixXd::Zero(unknowns, unknowns);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(unknowns, count);
  // Adds  sign * op * value  to the N condition rows starting at `row` (op empty = identity).
  const auto add = [&](Eigen::Index row, std::size_t slab, const Affine& value, const Eigen::MatrixXd& op,
                       double sign) {
    const bool identity = op.size() == 0;
    const auto apply = [&](const Eigen::MatrixXd& m) -> Eigen::MatrixXd { return identity ? m : op * m; };
    system.block(row, column[slab], n, n) += sign * apply(value.minus);
    if (value.plus.size() != 0) system.block(row, column[slab] + n, n, n) += sign * apply(value.plus);
    rhs.middleRows(row, n) -= sign * apply(value.constant);
  };
  const auto add_source = [&](Eigen::Index row, const Eigen::MatrixXd& source) {
    if (source.size() != 0) rhs.middleRows(row, n) += source;
  };
  const auto add_reflection = [&](Eigen::Index row, std::size_t slab, const Affine& value, const Eigen::MatrixXd& op) {
    if (op.size() != 0) add(row, slab, value, op, -1.0);
  };

  Eigen::Index row = 0;
  // Top: u-_1(0) - R_top u+_1(0) = source_top.
  add(row, 0, values[0].down_top, {}, 1.0);
  add_reflection(row, 0, values[0].up_top, slabs[0].reflect_top);
  add_source(row, slabs[0].source_top);
  row += n;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const FaceCoupling& face = faces[f];
    const SlabFaces& a = values[f];
    const SlabFaces& b = values[f + 1];
    // u+_a(tau_a) - R_a u-_a(tau_a) - T_up u+_b(0) = source_up.
    add(row, f, a.up_bottom, {}, 1.0);
    add_reflection(row, f, a.down_bottom, face.reflect_above);
    add(row, f + 1, b.up_top, face.transmit_up, -1.0);
    add_source(row, face.source_up);
    row += n;
    // u-_b(0) - R_b u+_b(0) - T_down u-_a(tau_a) = source_down.
    add(row, f + 1, b.down_top, {}, 1.0);
    add_reflection(row, f + 1, b.up_top, face.reflect_below);
    add(row, f, a.down_bottom, face.transmit_down, -1.0);
    add_source(row, face.source_down);
    row += n;
  }
  const BoundaryProblem& last = slabs.back();
  if (!values.back().semi_infinite) {
    // Bottom: u+_n(tau_n) - R_bottom u-_n(tau_n) = source_bottom.
    add(row, layers - 1, values.back().up_bottom, {}, 1.0);
    add_reflection(row, layers - 1, values.back().down_bottom, last.reflect_bottom);
    add_source(row, last.source_bottom);
  }

  const Eigen::MatrixXd c = Eigen::PartialPivLU<Eigen::MatrixXd>(system).solve(rhs);
  StackField field;
  for (std::size_t i = 0; i < layers; ++i) {
    NodeField slab;
    slab.c_minus = c.middleRows(column[i], n);
    slab.c_plus =
        values[i].semi_infinite ? Eigen::MatrixXd::Zero(n, count) : Eigen::MatrixXd(c.middleRows(column[i] + n, n));
    slab.up_top = values[i].up_top.at(slab.c_minus, slab.c_plus);
    field.down_top.push_back(values[i].down_top.at(slab.c_minus, slab.c_plus));
    if (values[i].semi_infinite) {
      slab.down_bottom = Eigen::MatrixXd::Zero(n, count);
      field.up_bottom.push_back(Eigen::MatrixXd::Zero(n, count));
    } else {
      slab.down_bottom = values[i].down_bottom.at(slab.c_minus, slab.c_plus);
      field.up_bottom.push_back(values[i].up_bottom.at(slab.c_minus, slab.c_plus));
    }
    field.slabs.push_back(std::move(slab));
  }
  return field;
}

}  // namespace skinlayer
