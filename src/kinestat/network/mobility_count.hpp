// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// FN and CN of a coupling network from a single rank, for screening many variants of one model
// (the design search tries hundreds): the full analysis also solves the cutset law, both
// contracted methods, pair freedoms and bases, which a count does not need.

#include <vector>

#include "kinestat/graph/coupling_graph.hpp"
#include "kinestat/linalg/rank_decision.hpp"
#include "kinestat/screw/coupling_basis.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::network {

/// The counts of one network: F freedoms, l independent circuits, m = rank of M^N.
struct MobilityCount {
  int F = 0;
  int l = 0;
  int m = 0;
  int FN = 0;  ///< F - m (seed 000, eq. 20a)
  int CN = 0;  ///< d l - m (the identity CN = d l - m of seed 000, section 2.6)
};

/// Counts the network of `bodies` joined by `edges` (coupling e joins edges[e].from to
/// edges[e].to) whose couplings have the unit motions of `bases[e]` (d coordinates, axis
/// formation, any one frame for all couplings). The rank of the circuit motion matrix M^N is
/// exact when `exact` (rational elimination), otherwise numerical with `tolerances.rank` (relative to
/// the largest singular value; give bases in a conditioned frame, see AnalysisFrame), its default
/// rule raised by `input_rounding` (AnalysisFrame::input_rounding of the model).
/// Throws graph::TreeError when the bodies are not all connected.
MobilityCount count_mobility(int bodies, const std::vector<graph::Edge>& edges,
                             const std::vector<const screw::CouplingBasis*>& bases, int d, bool exact,
                             const Tolerances& tolerances, double input_rounding = 0.0);

}  // namespace kinestat::network
