// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Everything the coupling-network analysis finds, as plain data (seed 000): the graph
// matrices, the unit matrices, ranks with their evidence, FN and CN, the motions and
// actions of every coupling in terms of primary variables, the motion of every body, and the
// motion system of every pair of bodies. Every screw, linear form and matrix here is in the
// user's frame and length unit (the analysis decides in a conditioned frame and converts once,
// docs/network.md); only rank evidence (singular values, thresholds) is of the conditioned
// matrices.

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

#include "kinestat/linalg/homogeneous_solution.hpp"
#include "kinestat/linalg/rational_matrix.hpp"
#include "kinestat/screw/coupling_basis.hpp"

namespace kinestat::network {

/// Table 2 of seed 000: the four subsets of coupling networks.
enum class NetworkClass {
  simply_stiff,                ///< FN = 0, CN = 0: statically determinate structure
  overconstrained_structure,   ///< FN = 0, CN > 0: redundant / statically indeterminate structure
  kinematic_chain,             ///< FN > 0, CN = 0: kinematically designed (exactly constrained) chain
  overconstrained_chain,       ///< FN > 0, CN > 0: overconstrained kinematic chain / mechanism
};

std::string class_id(NetworkClass c);
/// The subset of Table 2 that FN and CN put a network in.
NetworkClass classify(int FN, int CN);
std::string class_description(NetworkClass c);

/// Linear forms in the primary variables: row i of `values` gives quantity i as
/// sum_j values(i, j) * primary_j. `exact` holds the same when the analysis was exact.
struct LinearForms {
  Eigen::MatrixXd values;
  std::optional<linalg::RationalMatrix> exact;
};

/// One magnitude (unknown) of [c]F or [C]C.
struct Magnitude {
  std::string name;     ///< seed-style name, e.g. "sa", "Ub"
  int coupling = 0;     ///< index of its coupling
  screw::UnitScrew unit_screw;  ///< its unit screw, d coordinates in the user's frame
};

/// Motions or actions of one pair of bodies (seed 000, section 2.7 and Table 1).
struct PairSystem {
  int body_i = 0, body_j = 0;     ///< i < j; motions are those of j relative to i
  std::optional<int> coupling;    ///< the direct coupling this row describes, if any
  int f = 0, c = 0;               ///< gross dof / doc of the direct coupling (f = d, c = 0 if absent)
  int fij = 0, cij = 0;           ///< nett dof of the pair, nett doc of the direct coupling
  std::vector<int> motion_primaries;  ///< indices into NetworkResult::primary_motion that appear
  std::vector<int> action_primaries;  ///< indices into NetworkResult::primary_action that appear
  LinearForms motion_system;      ///< d rows: motion of j relative to i in the motion primaries
  LinearForms action_system;      ///< d rows: action transmitted by the coupling (zero if absent)
  linalg::RankDecision motion_rank, action_rank;
};

/// One of the two dual results for motions (or actions): a homogeneous solution and the
/// contracted matrix [M]d,e (or [A]d,e) it gives, as d*e linear forms (coupling-major).
struct MethodResult {
  linalg::HomogeneousSolution solution;  ///< of the method's own unknowns
  LinearForms contracted;                ///< rows: coupling 0 coordinates 0..d-1, coupling 1, ...
};

/// The rank of the user's rational M^N modulo large primes, beside a floating-point analysis of a
/// model of short decimals too large for exact elimination (analyse_network, automatic).
struct ModularCheck {
  int rank = 0;           ///< certain lower bound of the exact rank of M^N (equal to it but for unlucky primes)
  int primes = 0;         ///< primes used
  int agreeing = 0;       ///< primes that gave `rank`
  bool followed = false;  ///< the floating-point decisions differed and were moved to this rank
};

struct NetworkResult {
  std::string model_name;
  bool exact = false;                 ///< exact rational arithmetic was used
  std::string arithmetic_reason;      ///< why exact or floating point was chosen
  int d = 6;
  int bodies = 0, e = 0, l = 0, k = 0;
  int F = 0, C = 0, m = 0, a = 0, FN = 0, CN = 0;
  NetworkClass classification = NetworkClass::simply_stiff;
  int ground = 0;
  double length_scale = 1;            ///< characteristic length used to condition floating-point ranks

  std::vector<int> branches, chords;  ///< coupling indices; order of cutsets / circuits
  Eigen::MatrixXi B, Q, BM, QA;       ///< seed eqs 3a, 3b, 4a, 4b
  linalg::RationalMatrix MD, AD;      ///< unit matrices of direct couplings, d x F and d x C
  linalg::RationalMatrix MN, AN;      ///< network unit matrices, dl x F and dk x C (eqs 5a, 5b)

  std::vector<Magnitude> motions;     ///< the F unknowns of [c]F, in column order of MD
  std::vector<Magnitude> actions;     ///< the C unknowns of [C]C, in column order of AD
  std::vector<int> primary_motion;    ///< indices into `motions` (FN of them)
  std::vector<int> primary_action;    ///< indices into `actions` (CN of them)

  // The four methods. Circulation (i) and cutset (ii) laws solve MN c = 0 and AN C = 0;
  // the virtual power methods solve AN^T Mk = 0 (iii) and MN^T Al = 0 (iv).
  MethodResult circulation, cutset_law, cutset_motion, circuit_action;
  LinearForms motion_magnitudes;      ///< [c]F in the motion primaries (F rows)
  LinearForms action_magnitudes;      ///< [C]C in the action primaries (C rows)
  bool motion_methods_agree = false;  ///< (i) and (iii) give the same [M]d,e
  bool action_methods_agree = false;  ///< (ii) and (iv) give the same [A]d,e

  /// Each body's motion relative to the ground, by body index (the ground's is zero): d rows,
  /// one column per primary motion (the motion with that primary = 1 and the others 0), axis
  /// formation (ω; v) with v the velocity of the point at the user's origin, in the user's frame
  /// and length unit per unit of the primary. Body j's motion relative to body i is
  /// body_motions[j] − body_motions[i] (PairSystem::motion_system).
  std::vector<LinearForms> body_motions;

  std::vector<PairSystem> pairs;

  /// Identities of DESIGN.md (seed 000 eqs 7, 8, 16); all must hold.
  bool identities_hold = false;

  /// Numeric values of the magnitudes when values of primaries of that kind were given. With
  /// values for only some primaries, the magnitudes (and screw coordinates) that depend on a
  /// primary without a value are NaN, and the missing primaries are named below.
  std::optional<Eigen::VectorXd> motion_values, action_values;
  std::vector<std::string> missing_motion_values, missing_action_values;
  /// The same as screws: column e is coupling e's motion (axis formation) or action (ray
  /// formation), d coordinates in the user's frame.
  std::optional<Eigen::MatrixXd> coupling_motion_values, coupling_action_values;

  /// When exact arithmetic was used on long literals: the floating-point FN and CN, if they
  /// differ (the geometry is within rounding of a configuration with other FN, CN).
  std::optional<std::pair<int, int>> floating_point_disagreement;

  /// Set when the ranks were decided in floating point and checked by modular arithmetic.
  std::optional<ModularCheck> modular_check;
};

}  // namespace kinestat::network
