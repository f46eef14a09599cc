// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/framework/generic_framework.hpp"

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>

#include "kinestat/framework/rigid_mode_basis.hpp"
#include "kinestat/linalg/homogeneous_solution.hpp"
#include "kinestat/linalg/modular_rank.hpp"
#include "kinestat/linalg/seeded_random.hpp"
#include "kinestat/linalg/sign_convention.hpp"
#include "kinestat/linalg/svd_analysis.hpp"

namespace kinestat::framework {

namespace {

using Eigen::Index;
using linalg::SeededRandom;

// Random positions are whole numbers up to 2^20 (see network/generic_network.cpp for why).
constexpr std::int64_t kRandomRange = std::int64_t{1} << 20;
constexpr std::uint64_t kRealisationSeeds[] = {0x6672616d65776b31ULL, 0x6672616d65776b32ULL};
constexpr std::uint64_t kPerturbationSeed = 0x6e75646765667231ULL;

bool bars_only(const FrameworkModel& model) {
  return std::all_of(model.elements.begin(), model.elements.end(), [](const Element& e) { return e.type == ElementType::truss; });
}

using Positions = std::vector<std::array<std::int64_t, 3>>;

Positions random_positions(const FrameworkModel& model, SeededRandom& random) {
  Positions positions(model.nodes.size());
  for (auto& p : positions)
    for (int i = 0; i < 3; ++i) p[static_cast<std::size_t>(i)] = i < model.dimension ? random.integer(kRandomRange) : 0;
  return positions;
}

// Rank of D(c) of a bar framework at integer positions, modulo every prime: each bar's row is
// its direction p − q unnormalised (a row scaled by the bar's length has the same rank).
Index modular_bar_rank(const FrameworkModel& model, const FrameworkResult& given, const Positions& positions) {
  std::vector<Index> column(given.indexing.coordinates.size(), -1);
  for (std::size_t j = 0; j < given.partition.dependent_coordinates.size(); ++j)
    column[static_cast<std::size_t>(given.partition.dependent_coordinates[j])] = static_cast<Index>(j);
  Index best = 0;
  for (std::uint64_t prime : linalg::kModularPrimes) {
    linalg::ModularMatrix d(given.m, given.n, prime);
    const auto residue = [prime](std::int64_t x) {
      const auto p = static_cast<std::int64_t>(prime);
      return static_cast<std::uint64_t>(((x % p) + p) % p);
    };
    for (Index i = 0; i < given.m; ++i) {
      const DeformationRef& ref = given.indexing.deformations[static_cast<std::size_t>(given.rows[static_cast<std::size_t>(i)])];
      const Element& element = model.elements[ref.element];
      const std::size_t p = element.nodes[0], q = element.nodes[1];
      for (int slot = 0; slot < 3; ++slot) {
        const auto s = static_cast<std::size_t>(slot);
        const std::int64_t difference = positions[p][s] - positions[q][s];
        const Index cp = given.indexing.coordinate_of[p][s], cq = given.indexing.coordinate_of[q][s];
        if (cp >= 0 && column[static_cast<std::size_t>(cp)] >= 0) d(i, column[static_cast<std::size_t>(cp)]) = residue(difference);
        if (cq >= 0 && column[static_cast<std::size_t>(cq)] >= 0) d(i, column[static_cast<std::size_t>(cq)]) = residue(-difference);
      }
    }
    best = std::max(best, linalg::modular_rank(d));
  }
  return best;
}

// A beam's element frame at new node positions: x from p to q, y as close to `hint` as
// possible (planar beams keep local z along global z).
Eigen::Matrix3d beam_frame(int dimension, const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& hint) {
  const Eigen::Vector3d x = (q - p).normalized();
  Eigen::Vector3d y = dimension == 2 ? Eigen::Vector3d::UnitZ().cross(x) : Eigen::Vector3d(hint - hint.dot(x) * x);
  if (y.norm() < 1e-9) y = x.unitOrthogonal();
  y.normalize();
  Eigen::Matrix3d frame;
  frame << x, y, x.cross(y);
  return frame;
}

// The model with its nodes moved to `positions`; beam frames follow their nodes, their
// cross-sections turned to `hints` (one per element).
FrameworkModel moved(const FrameworkModel& model, const std::vector<Eigen::Vector3d>& positions, const std::vector<Eigen::Vector3d>& hints) {
  FrameworkModel out = model;
  for (std::size_t n = 0; n < out.nodes.size(); ++n) out.nodes[n].position = positions[n];
  for (std::size_t e = 0; e < out.elements.size(); ++e) {
    Element& element = out.elements[e];
    if (element.type != ElementType::beam) continue;
    element.frame = beam_frame(model.dimension, positions[element.nodes[0]], positions[element.nodes[1]], hints[e]);
  }
  return out;
}

Eigen::Vector3d random_vector(SeededRandom& random, int dimension) {
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  for (int i = 0; i < dimension; ++i) v(i) = random.symmetric();
  return v;
}

// Floating-point rank of D(c) at a random realisation (beams and rigid bodies, whose
// deformation functions normalise lengths and directions).
Index floating_rank(const FrameworkModel& model, SeededRandom& random) {
  std::vector<Eigen::Vector3d> positions, hints;
  for (std::size_t n = 0; n < model.nodes.size(); ++n) positions.push_back(random_vector(random, model.dimension));
  for (std::size_t e = 0; e < model.elements.size(); ++e) hints.push_back(random_vector(random, 3));
  FrameworkResult scratch;
  const Eigen::MatrixXd jacobian(prepare_analysis(moved(model, positions, hints), scratch));
  if (jacobian.size() == 0) return 0;
  return linalg::numerical_rank(jacobian).rank;
}

Eigen::MatrixXd columns_of(const std::vector<Eigen::VectorXd>& vectors, Index rows) {
  Eigen::MatrixXd m(rows, static_cast<Index>(vectors.size()));
  for (std::size_t j = 0; j < vectors.size(); ++j) m.col(static_cast<Index>(j)) = vectors[j];
  return m;
}

// A canonical basis of the span of `columns` (reduced echelon form, earliest free variables,
// the analysis's rule), each column oriented by the one sign convention.
Eigen::MatrixXd canonical(const Eigen::MatrixXd& columns) {
  if (columns.cols() == 0) return columns;
  std::vector<Index> free_variables;
  const Eigen::MatrixXd q = Eigen::HouseholderQR<Eigen::MatrixXd>(columns).householderQ() *
                            Eigen::MatrixXd::Identity(columns.rows(), columns.cols());
  Eigen::MatrixXd basis = linalg::echelon_null_basis(q, free_variables);
  if (basis.cols() != columns.cols()) basis = q;
  for (Index j = 0; j < basis.cols(); ++j) linalg::orient_unit_vector(basis.col(j), kModeZero);
  return basis;
}

// The states `given` (columns) re-chosen as [persisting part, the rest]: the projection of the
// persisting states onto their span first, then its complement in that span.
Eigen::MatrixXd rebase(const Eigen::MatrixXd& given, const Eigen::MatrixXd& persisting) {
  const Index k = given.cols(), g = persisting.cols();
  const Eigen::MatrixXd q = Eigen::HouseholderQR<Eigen::MatrixXd>(given).householderQ() * Eigen::MatrixXd::Identity(given.rows(), k);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(q.transpose() * persisting, Eigen::ComputeFullU);
  Eigen::MatrixXd basis(given.rows(), k);
  basis << canonical(q * svd.matrixU().leftCols(g)), canonical(q * svd.matrixU().rightCols(k - g));
  return basis;
}

}  // namespace

FrameworkResult with_generic_basis(const FrameworkModel& model, FrameworkResult analysis, const GenericFramework& generic,
                                   const AnalysisOptions& options) {
  if (generic.mode_basis) {
    analysis.modes.clear();
    collect_modes(analysis, *generic.mode_basis);
    classify_second_order(model, analysis, options);
  }
  if (generic.stress_basis) {
    analysis.stresses.clear();
    collect_stresses(analysis, *generic.stress_basis);
  }
  return analysis;
}

std::optional<LamanCount> laman_count(const FrameworkModel& model, const FrameworkResult& given) {
  if (model.dimension != 2 || !bars_only(model)) return std::nullopt;
  const std::size_t nodes = model.nodes.size();
  const std::size_t ground0 = nodes, ground1 = nodes + 1;
  std::vector<std::pair<std::size_t, std::size_t>> bars{{ground0, ground1}};
  for (std::size_t n = 0; n < nodes; ++n) {
    int removed = 0;
    for (int slot = 0; slot < 2; ++slot) removed += model.nodes[n].roles[static_cast<std::size_t>(slot)] != CoordinateRole::dependent ? 1 : 0;
    if (removed >= 1) bars.emplace_back(n, ground0);
    if (removed == 2) bars.emplace_back(n, ground1);
  }
  const std::size_t supports = bars.size();
  for (const Element& element : model.elements)
    if (element.roles.front() != DeformationRole::released) bars.emplace_back(element.nodes[0], element.nodes[1]);
  const PebbleGame game = pebble_game(nodes + 2, bars);
  LamanCount count;
  count.rank = static_cast<Index>(game.independent) - static_cast<Index>(supports);
  count.mechanisms = given.n - count.rank;
  count.self_stresses = given.m - count.rank;
  for (const auto& vertices : game.rigid_components) {
    LamanCount::Component component;
    for (std::size_t v : vertices) {
      if (v < nodes) component.nodes.push_back(v);
      else component.ground = true;
    }
    if (!component.nodes.empty()) count.rigid_components.push_back(component);
  }
  return count;
}

std::optional<GenericFramework> generic_framework(const FrameworkModel& model, const FrameworkResult& given) {
  if (std::max(given.m, given.n) > kGenericFrameworkLimit) return std::nullopt;
  GenericFramework g;
  g.exact = bars_only(model);
  for (std::uint64_t seed : kRealisationSeeds) {
    SeededRandom random(seed);
    const Index rank = g.exact ? modular_bar_rank(model, given, random_positions(model, random)) : floating_rank(model, random);
    g.rank = std::max(g.rank, rank);
    ++g.realisations;
  }
  // A specialisation never has a larger rank; a smaller generic rank would be an unlucky draw.
  g.rank = std::max(g.rank, given.rank);
  g.mechanisms = given.n - g.rank;
  g.self_stresses = given.m - g.rank;

  linalg::CauseSplit modes = linalg::split_by_count(static_cast<Index>(given.modes.size()), g.mechanisms);
  linalg::CauseSplit stresses = linalg::split_by_count(static_cast<Index>(given.stresses.size()), g.self_stresses);
  const bool mixed_modes = g.mechanisms > 0 && g.mechanisms < given.mechanisms;
  const bool mixed_stresses = g.self_stresses > 0 && g.self_stresses < given.self_stresses;
  const bool complete = static_cast<Index>(given.modes.size()) == given.mechanisms &&
                        static_cast<Index>(given.stresses.size()) == given.self_stresses;
  if ((mixed_modes || mixed_stresses) && given.vectors && complete) {
    SeededRandom random(kPerturbationSeed);
    const double step = kFrameworkCausePerturbation * given.length;
    std::vector<Eigen::Vector3d> positions, hints;
    for (const Node& node : model.nodes) positions.push_back(node.position + step * random_vector(random, model.dimension));
    for (const Element& element : model.elements) hints.push_back(element.frame.col(1));
    FrameworkResult perturbed;
    const Eigen::MatrixXd jacobian(prepare_analysis(moved(model, positions, hints), perturbed));
    const linalg::SvdAnalysis svd = linalg::analyse_svd(jacobian);
    // Null vectors of the scaled matrix back in D̂'s units, as the analysis reports its states.
    const auto split = [](const Eigen::MatrixXd& given_states, const Eigen::MatrixXd& persisting, std::optional<Eigen::MatrixXd>& basis) {
      basis = rebase(given_states, persisting);
      return linalg::split_by_subspace(*basis, persisting);
    };
    if (mixed_modes) {
      std::vector<Eigen::VectorXd> vectors;
      for (const auto& mode : given.modes) vectors.push_back(mode.velocities);
      modes = split(columns_of(vectors, given.n), perturbed.column_scale.asDiagonal() * svd.v.rightCols(g.mechanisms), g.mode_basis);
    }
    if (mixed_stresses) {
      std::vector<Eigen::VectorXd> vectors;
      for (const auto& state : given.stresses) vectors.push_back(state.resultants);
      stresses = split(columns_of(vectors, given.m), perturbed.row_scale.asDiagonal() * svd.u.rightCols(g.self_stresses), g.stress_basis);
    }
  }
  g.mode_causes = modes.causes;
  g.stress_causes = stresses.causes;
  g.split_residual = std::max(modes.residual, stresses.residual);
  g.laman = laman_count(model, given);
  return g;
}

FrameworkResult analyse_framework_as_reported(const FrameworkModel& model, const AnalysisOptions& options,
                                              std::optional<GenericFramework>* generic) {
  FrameworkResult analysis = analyse_framework(model, options);
  options.stop.throw_if_requested();
  std::optional<GenericFramework> answer = generic_framework(model, analysis);
  options.stop.throw_if_requested();
  if (answer) analysis = with_generic_basis(model, std::move(analysis), *answer, options);
  separate_rigid_motions(model, analysis, answer, options);
  if (generic != nullptr) *generic = std::move(answer);
  return analysis;
}

}  // namespace kinestat::framework
