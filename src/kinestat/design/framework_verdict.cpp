// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/design/framework_verdict.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>
#include "kinestat/tolerances.hpp"

namespace kinestat::design {

namespace {

using framework::FrameworkResult;
using framework::FrameworkModel;

}  // namespace

std::string framework_row_name(const FrameworkModel& model, const FrameworkResult& analysis, Eigen::Index row) {
  const auto& d = analysis.indexing.deformations[static_cast<std::size_t>(analysis.rows[static_cast<std::size_t>(row)])];
  const auto& element = model.elements[d.element];
  return element.name + "." + framework::deformation_names(model, element)[d.deformation];
}

std::string framework_column_name(const FrameworkModel& model, const FrameworkResult& analysis, Eigen::Index column) {
  const auto& c = analysis.indexing.coordinates[static_cast<std::size_t>(
      analysis.partition.dependent_coordinates[static_cast<std::size_t>(column)])];
  return model.nodes[c.node].name + "." + framework::kSlotNames[static_cast<std::size_t>(c.slot)];
}

Verdict framework_verdict(const FrameworkModel& model, const FrameworkResult& a, const framework::AnalysisOptions& options) {
  Verdict v;
  v.extra_motions = static_cast<int>(a.mechanisms);
  v.redundant_constraints = static_cast<int>(a.self_stresses);
  v.exactly_constrained = a.exactly_constrained();
  v.intended_motions = static_cast<int>(a.count.declared_dof());
  v.intended_basis = "declared independent coordinates and deformations ('independent:')";
  v.summary = summary_sentence(v.extra_motions, v.redundant_constraints, v.intended_motions);
  note_near_rank_change(v, a.decision.distance(), a.mechanisms > 0);

  // Rigid motions of the whole model first, as one state (rigid_mode_basis.hpp names them).
  std::vector<std::string> rigid;
  for (const auto& mode : a.modes)
    if (!mode.rigid_motion.empty()) rigid.push_back(mode.rigid_motion);
  if (!rigid.empty()) {
    const bool unsupported = static_cast<int>(rigid.size()) == (model.dimension == 2 ? 3 : 6);
    VerdictState state{"extra motion",
                       unsupported ? fmt::format("no supports: {} rigid motions", rigid.size())
                                   : fmt::format("not enough supports: {}", fmt::join(rigid, "; ")),
                       {}};
    for (const auto& name : rigid) state.participants.push_back({"motion", name, 1.0 / static_cast<double>(rigid.size()), "rigid-body motion"});
    v.states.push_back(std::move(state));
  }
  std::size_t internal = 0;
  for (std::size_t k = 0; k < a.modes.size(); ++k) {
    if (!a.modes[k].rigid_motion.empty()) continue;
    ++internal;
    const std::string order = k < a.orders.size() && a.orders[k].order != framework::MotionOrder::undetermined
                                  ? std::string(framework::motion_order_name(a.orders[k].order)) + " "
                                  : "";
    VerdictState state{"extra motion",
                       rigid.empty() ? fmt::format("kinematically indeterminate mode {}", k + 1)
                                     : fmt::format("internal {}mode {} (mode {} of the report)", order, internal, k + 1),
                       {}};
    const Eigen::VectorXd& velocity = a.modes[k].velocities;
    for (Eigen::Index col : a.modes[k].moving) {
      const double share = velocity(col) * velocity(col) / std::max(velocity.squaredNorm(), 1e-300);
      if (share > kShareZero)
        state.participants.push_back({"coordinate", framework_column_name(model, a, col), share,
                                      velocity(col) > 0 ? "moves +" : "moves -"});
    }
    rank_participants(state.participants);
    v.states.push_back(std::move(state));
  }
  for (std::size_t k = 0; k < a.stresses.size(); ++k) {
    VerdictState state{"self-stress", fmt::format("statically indeterminate stress state {}", k + 1), {}};
    const Eigen::VectorXd& stress = a.stresses[k].resultants;
    for (Eigen::Index row = 0; row < stress.size(); ++row) {
      const double share = stress(row) * stress(row) / std::max(stress.squaredNorm(), 1e-300);
      if (share > kShareZero)
        state.participants.push_back({"deformation", framework_row_name(model, a, row), share,
                                      stress(row) > 0 ? "positive resultant" : "negative resultant"});
    }
    rank_participants(state.participants);
    v.states.push_back(std::move(state));
  }
  v.motion_participants = strongest(v.states, "extra motion");
  v.constraint_participants = strongest(v.states, "self-stress");

  if (v.exactly_constrained) {
    v.changes_verified = true;
    v.becomes = "unchanged: already exactly constrained";
    return v;
  }
  if (!a.vectors) {
    v.note = "the model is too large for the dense SVD: no modes, stress states or proposal were computed";
    return v;
  }
  for (Eigen::Index row : a.releases)
    v.changes.push_back({"release", "deformation", framework_row_name(model, a, row), "released",
                         "removes a redundant constraint (a state of self-stress)", "fixed", {}});
  for (Eigen::Index col : a.constrain)
    v.changes.push_back({"constrain", "coordinate", framework_column_name(model, a, col), "independent",
                         "removes an extra motion: fix this coordinate or drive it as an input", "dependent", {}});

  // Verified by re-analysis of the changed copy, never assumed.
  const FrameworkModel changed = framework::apply_proposal(model, a);
  framework::AnalysisOptions counts_only = options;
  counts_only.vectors = false;
  counts_only.sparse_vectors = 0;
  const FrameworkResult after = framework::analyse_framework(changed, counts_only);
  v.changes_verified = after.exactly_constrained();
  v.becomes = fmt::format("{}: D(c) {} x {}, rank {}; {} declared", after.exactly_constrained() ? "exactly constrained" : "still not exactly constrained",
                          after.m, after.n, after.rank,
                          counted(after.count.declared_dof(), "degree of freedom", "degrees of freedom"));
  return v;
}

}  // namespace kinestat::design
