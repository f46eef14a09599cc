// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/network/generic_network.hpp"

#include <algorithm>

#include "kinestat/linalg/modular_rank.hpp"
#include "kinestat/linalg/seeded_random.hpp"
#include "kinestat/linalg/svd_analysis.hpp"
#include "kinestat/network/analysis_frame.hpp"
#include "kinestat/network/unit_matrices.hpp"

namespace kinestat::network {

namespace {

using Eigen::Index;
using linalg::SeededRandom;
using screw::Rational;
using screw::Vec3;

// Random coordinates are whole numbers up to 2^20: a realisation is special only where a
// polynomial in them vanishes, which for numbers drawn from 2^21 values has a chance below
// (degree / 2^21) per realisation; two realisations are ranked and the larger rank kept.
constexpr std::int64_t kRandomRange = std::int64_t{1} << 20;
constexpr std::uint64_t kRealisationSeeds[] = {0x6b696e6573746174ULL, 0x67656e6572696331ULL};
constexpr std::uint64_t kPerturbationSeed = 0x7065727475726231ULL;
constexpr std::uint64_t kSpecialSeed = 0x7370656369616c31ULL;

bool along_z(const Vec3& a) { return sgn(a[0]) == 0 && sgn(a[1]) == 0; }

Rational largest_magnitude(const Vec3& a) { return std::max({abs(a[0]), abs(a[1]), abs(a[2])}); }

// How a coupling's geometry is replaced: by a random one, or by the given one moved by a small
// random amount `delta` (relative to each quantity's size; lengths in the analysis frame).
struct Placement {
  SeededRandom& random;
  bool planar;                    // planar models keep points in the plane and axes normal to it
  std::optional<Rational> delta;  // empty: random realisation

  Rational draw() { return Rational(random.integer(kRandomRange)); }
  Rational nudge(const Rational& size) { return *delta * size * Rational(random.integer(kRandomRange), kRandomRange); }

  Vec3 vector(const Vec3& given, const Rational& size) {
    Vec3 v = given;
    for (std::size_t i = 0; i < 3; ++i) {
      if (planar && i == 2) continue;
      v[i] = delta ? Rational(given[i] + nudge(size)) : draw();
    }
    return v;
  }
  Vec3 point(const Vec3& p) { return vector(p, 1); }
  std::optional<Vec3> direction(const std::optional<Vec3>& a) {
    if (!a) return planar ? a : std::optional<Vec3>(vector({0, 0, 1}, 1));  // the default axis is z
    if (planar && along_z(*a)) return a;
    Vec3 v = vector(*a, largest_magnitude(*a));
    if (screw::is_zero(v)) v = *a;
    return v;
  }
  screw::CouplingGeometry geometry(const screw::CouplingGeometry& g, int d) {
    screw::CouplingGeometry out = g;
    out.point = point(g.point);
    out.axis = direction(g.axis);
    out.axis2 = direction(g.axis2);
    out.normal = direction(g.normal);
    out.pitch = delta ? Rational(g.pitch + nudge(1)) : Rational(draw() / kRandomRange);
    for (auto& screw : out.custom_motions) {
      Rational size = 0;
      for (const Rational& x : screw) size = std::max<Rational>(size, abs(x));
      for (int i = 0; i < d; ++i) screw[static_cast<std::size_t>(i)] = delta ? Rational(screw[static_cast<std::size_t>(i)] + nudge(size)) : draw();
    }
    out.custom_actions.clear();  // recomputed as the reciprocal complement of the new motions
    return out;
  }
};

std::optional<std::vector<screw::CouplingBasis>> bases_of(const Model& model, const std::vector<screw::CouplingGeometry>& geometry) {
  std::vector<screw::CouplingBasis> bases;
  try {
    for (std::size_t i = 0; i < model.couplings.size(); ++i)
      bases.push_back(screw::coupling_basis(model.couplings[i].type, geometry[i], model.space));
  } catch (const screw::GeometryError&) {
    return std::nullopt;  // a degenerate draw (e.g. parallel universal axes): practically never
  }
  return bases;
}

std::vector<screw::CouplingGeometry> given_geometry(const Model& model) {
  std::vector<screw::CouplingGeometry> g;
  for (const auto& c : model.couplings) g.push_back(c.geometry);
  return g;
}

// Rank of M^N modulo the primes, or nothing when the coupling bases change size (a type whose
// freedoms depend on its geometry) or cannot be built.
std::optional<int> modular_motion_rank(const Model& model, const NetworkResult& given,
                                       const std::vector<screw::CouplingGeometry>& geometry) {
  const auto bases = bases_of(model, geometry);
  if (!bases) return std::nullopt;
  const UnitMatrices u = unit_matrices(*bases, given.d, given.B, given.Q);
  if (u.MD.cols() != given.F || u.AD.cols() != given.C) return std::nullopt;
  return static_cast<int>(linalg::modular_rank(u.MN).rank);
}

// d·e × (F or C): each coupling's unit screws in its own d rows, so a vector of magnitudes maps
// to the screws of all couplings (coordinates that do not depend on how a basis was chosen).
Eigen::MatrixXd coupling_screws(const linalg::RationalMatrix& unit, const std::vector<int>& first, int d) {
  const Eigen::MatrixXd u = unit.to_double();
  const auto couplings = static_cast<Index>(first.size()) - 1;
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(d * couplings, u.cols());
  for (Index e = 0; e < couplings; ++e)
    for (int j = first[static_cast<std::size_t>(e)]; j < first[static_cast<std::size_t>(e) + 1]; ++j) g.block(e * d, j, d, 1) = u.col(j);
  return g;
}

// Causes of the columns of `given` (d·e coupling screws of each primary's state) when
// `persisting` of them persist, against the states of the slightly changed network.
linalg::CauseSplit split_by_perturbation(const Eigen::MatrixXd& given, const Eigen::MatrixXd& perturbed_network,
                                         const Eigen::MatrixXd& perturbed_screws, int persisting) {
  const linalg::SvdAnalysis svd = linalg::analyse_svd(perturbed_network, {}, linalg::SvdVectors::right_only);
  return linalg::split_by_subspace(given, perturbed_screws * svd.v.rightCols(persisting));
}

}  // namespace

std::optional<GenericNetwork> generic_network(const Model& model, const NetworkResult& given) {
  const bool planar = model.space.is_planar();
  if (!planar && !model.space.is_spatial()) return std::nullopt;
  GenericNetwork g;
  g.m = -1;
  for (std::uint64_t seed : kRealisationSeeds) {
    SeededRandom random(seed);
    Placement place{random, planar, std::nullopt};
    std::vector<screw::CouplingGeometry> geometry;
    for (const auto& c : model.couplings) geometry.push_back(place.geometry(c.geometry, given.d));
    const auto rank = modular_motion_rank(model, given, geometry);
    if (!rank) continue;
    g.m = std::max(g.m, *rank);
    ++g.realisations;
  }
  if (g.m < 0) return std::nullopt;
  // A specialisation never has a larger rank; a smaller generic rank would be an unlucky draw.
  g.m = std::max(g.m, given.m);
  g.primes = static_cast<int>(std::size(linalg::kModularPrimes));
  g.FN = given.F - g.m;
  g.CN = given.d * given.l - g.m;

  const bool mixed_motions = g.FN > 0 && g.FN < given.FN;
  const bool mixed_actions = g.CN > 0 && g.CN < given.CN;
  linalg::CauseSplit motions = linalg::split_by_count(given.FN, g.FN);
  linalg::CauseSplit actions = linalg::split_by_count(given.CN, g.CN);
  if (mixed_motions || mixed_actions) {
    const AnalysisFrame frame = AnalysisFrame::of(model);
    SeededRandom random(kPerturbationSeed);
    Placement place{random, planar, Rational(1, 1000000)};
    std::vector<screw::CouplingGeometry> framed, perturbed;
    for (const auto& c : model.couplings) {
      framed.push_back(frame.to_frame(c.geometry, model.space));
      perturbed.push_back(place.geometry(framed.back(), given.d));
    }
    const auto given_bases = bases_of(model, framed);
    const auto perturbed_bases = bases_of(model, perturbed);
    if (given_bases && perturbed_bases) {
      const UnitMatrices u0 = unit_matrices(*given_bases, given.d, given.B, given.Q);
      const UnitMatrices u1 = unit_matrices(*perturbed_bases, given.d, given.B, given.Q);
      if (mixed_motions)
        motions = split_by_perturbation(coupling_screws(u0.MD, u0.first_motion, given.d) * given.motion_magnitudes.values,
                                        u1.MN.to_double(), coupling_screws(u1.MD, u1.first_motion, given.d), g.FN);
      if (mixed_actions)
        actions = split_by_perturbation(coupling_screws(u0.AD, u0.first_action, given.d) * given.action_magnitudes.values,
                                        u1.AN.to_double(), coupling_screws(u1.AD, u1.first_action, given.d), g.CN);
    }
  }
  g.motion_causes = motions.causes;
  g.action_causes = actions.causes;
  g.split_residual = std::max(motions.residual, actions.residual);

  const auto rows = static_cast<double>(given.d * given.l), cols = static_cast<double>(given.F);
  const double work = static_cast<double>(given.e) * rows * cols * std::min(rows, cols);
  if (given.exact && given.m < g.m && work <= kSpecialCouplingWork) {
    std::vector<int> special;
    const std::vector<screw::CouplingGeometry> geometry = given_geometry(model);
    for (int e = 0; e < given.e; ++e) {
      SeededRandom random(kSpecialSeed + static_cast<std::uint64_t>(e));
      Placement place{random, planar, std::nullopt};
      std::vector<screw::CouplingGeometry> changed = geometry;
      changed[static_cast<std::size_t>(e)] = place.geometry(geometry[static_cast<std::size_t>(e)], given.d);
      const auto rank = modular_motion_rank(model, given, changed);
      if (rank && *rank > given.m) special.push_back(e);
    }
    g.special_couplings = special;
  }
  return g;
}

}  // namespace kinestat::network
