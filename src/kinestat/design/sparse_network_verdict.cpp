// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/design/sparse_network_verdict.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "kinestat/design/network_verdict.hpp"
#include "kinestat/design/screw_text.hpp"
#include "kinestat/network/magnitude_names.hpp"
#include "kinestat/screw/coupling_basis.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::design {

namespace {

using network::Model;
using network::SparseNetworkResult;
using Index = Eigen::Index;

// True unless body b's actions in K (the rows of its own couplings `couplings` in its column
// block) clearly span all d twists (kIdleSpinScreen): a floating-point screen that keeps the
// exact small-model analysis below for the bodies that might spin; most bodies of a network
// cannot, and the screen costs one SVD of at most a few dozen rows. The actions are taken
// about the centre of the body's own coupling points, lengths over their extent: whether a
// body can spin is a property of its couplings alone, and in K's frame (the whole network's
// centroid and extent) the couplings of one small body look nearly concurrent, so that a ring
// of 3·10⁴ revolutes sent every body to the exact analysis (GMP, half the command).
bool may_spin(const Model& model, const SparseNetworkResult& r, int b, const std::vector<std::size_t>& couplings,
              const Tolerances& tolerances) {
  if (r.K.cols() == 0) return true;
  const Index d = r.d, first = (b < r.ground ? b : b - 1) * d;
  std::map<Index, Index> local;  // row of K -> row of the block
  for (Index k = 0; k < d; ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(r.K, first + k); it; ++it) local.try_emplace(it.row(), static_cast<Index>(local.size()));
  if (static_cast<Index>(local.size()) < d) return true;
  Eigen::MatrixXd block = Eigen::MatrixXd::Zero(static_cast<Index>(local.size()), d);
  for (Index k = 0; k < d; ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(r.K, first + k); it; ++it) block(local[it.row()], k) = it.value();
  // The centre and extent of the body's coupling points, in K's frame ((p − origin) / scale).
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> points;
  for (const std::size_t i : couplings) {
    const auto& p = model.couplings[i].geometry.point;
    points.emplace_back((Eigen::Vector3d(p[0].get_d(), p[1].get_d(), p[2].get_d()) - r.frame.origin) / r.frame.scale);
    centre += points.back();
  }
  centre /= static_cast<double>(points.size());
  double extent = 0.0;
  for (const auto& p : points) extent = std::max(extent, (p - centre).norm());
  if (!(extent > 0.0)) extent = 1.0;
  const std::vector<int>& components = model.space.components;
  for (Index row = 0; row < block.rows(); ++row) {
    // (m; f) about K's origin -> ((m − c × f) / extent; f) about the centre.
    Screw6 action = Screw6::Zero();
    for (Index k = 0; k < d; ++k) action(components[static_cast<std::size_t>(k)]) = block(row, k);
    action.head<3>() = (Eigen::Vector3d(action.head<3>()) - centre.cross(Eigen::Vector3d(action.tail<3>()))) / extent;
    for (Index k = 0; k < d; ++k) block(row, k) = action(components[static_cast<std::size_t>(k)]);
  }
  const Eigen::VectorXd sigma = Eigen::JacobiSVD<Eigen::MatrixXd>(block).singularValues();
  const double relative = tolerances.rank.value_or(linalg::default_relative_tolerance(block.rows(), d, r.rank.input_rounding));
  return !(sigma(d - 1) > std::max(kIdleSpinScreen, kIdleSpinScreenMargin * relative) * sigma(0));
}

}  // namespace

// Idle spins body by body: each body that may spin (may_spin) with its own couplings, all ending
// at one stand-in for the rest of the network (the ground of the small model), so the cost is
// linear in the couplings.
std::vector<IdleMotion> sparse_idle_spins(const Model& model, const SparseNetworkResult& r, const Tolerances& tolerances) {
  const int ground = r.ground;
  std::vector<std::vector<std::size_t>> touching(model.bodies.size());
  for (std::size_t i = 0; i < model.couplings.size(); ++i) {
    touching[static_cast<std::size_t>(model.couplings[i].from)].push_back(i);
    touching[static_cast<std::size_t>(model.couplings[i].to)].push_back(i);
  }
  std::vector<IdleMotion> spins;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    if (static_cast<int>(b) == ground || touching[b].empty()) continue;
    if (touching[b].size() == 1) {
      // A body held by one coupling is free on its own with all that coupling's freedoms (as
      // idle_motions), unless the coupling is a declared input or the network has no circuit.
      const network::Coupling& c = model.couplings[touching[b].front()];
      const bool open = model.couplings.size() + 1 <= model.bodies.size();
      if (open || std::find(model.inputs.begin(), model.inputs.end(), c.name) != model.inputs.end()) continue;
      IdleMotion leaf{static_cast<int>(b), 0, {}, static_cast<int>(touching[b].front())};
      for (const auto& motion : screw::coupling_basis(c.type, c.geometry, model.space).motions) {
        std::vector<double> coordinates;
        for (const auto& x : motion.coordinates) coordinates.push_back(x.get_d());
        leaf.screws.push_back(std::move(coordinates));
      }
      leaf.count = static_cast<int>(leaf.screws.size());
      if (leaf.count > 0) spins.push_back(std::move(leaf));
      continue;
    }
    if (!may_spin(model, r, static_cast<int>(b), touching[b], tolerances)) continue;
    Model star;
    star.space = model.space;
    star.bodies = {model.bodies[b], "the rest"};
    star.ground = 1;
    for (std::size_t i : touching[b]) {
      network::Coupling c = model.couplings[i];
      c.from = c.from == static_cast<int>(b) ? 0 : 1;
      c.to = c.to == static_cast<int>(b) ? 0 : 1;
      star.couplings.push_back(std::move(c));
    }
    for (IdleMotion& idle : idle_motions(star, false, tolerances)) {
      idle.body = static_cast<int>(b);
      spins.push_back(std::move(idle));
    }
  }
  return spins;
}

namespace {

// Sizes of the result's wrenches and twists in its conditioned analysis frame (placement- and
// unit-free), for the shares.
struct Conditioning {
  network::SparseAnalysisFrame frame;
  const screw::ScrewSpace* space = nullptr;

  double wrench_size(const Screw6& w) const {
    const Eigen::Vector3d f = w.tail<3>();
    return f.squaredNorm() + ((Eigen::Vector3d(w.head<3>()) - frame.origin.cross(f)) / frame.scale).squaredNorm();
  }
  double twist_size(const Eigen::Ref<const Eigen::VectorXd>& twist) const { return frame.twist_to_frame(twist, *space).squaredNorm(); }
  double scale() const { return frame.scale; }
};

Screw6 screw_of(const screw::RoundedUnitScrew& s, const screw::ScrewSpace& space) {
  return embed(std::vector<double>(s.coordinates.begin(), s.coordinates.begin() + space.dimension()), space);
}

// Self-stress `j` of the sparse QR's basis: the wrench each coupling transmits, ranked by its size.
VerdictState self_stress_state(const Model& model, const SparseNetworkResult& r, const std::vector<Index>& first_row,
                               const Conditioning& frame, Index j) {
  const Index primary = r.stress_primaries[static_cast<std::size_t>(j)];
  const Eigen::VectorXd lambda = r.stress_basis.col(j);  // the primary = 1
  const double zero = kSupportZero * lambda.cwiseAbs().maxCoeff();
  std::map<int, Screw6> wrench;  // by coupling, user frame
  for (Index row = 0; row < lambda.size(); ++row) {
    if (std::abs(lambda(row)) <= zero) continue;
    const int c = r.row_coupling[static_cast<std::size_t>(row)];
    const Screw6 unit = screw_of(r.row_actions[static_cast<std::size_t>(row)], model.space);
    auto [it, inserted] = wrench.emplace(c, Screw6::Zero());
    it->second += lambda(row) * unit;
  }
  const int c = r.row_coupling[static_cast<std::size_t>(primary)];
  const auto k = static_cast<int>(primary - first_row[static_cast<std::size_t>(c)]);
  const auto& coupling = model.couplings[static_cast<std::size_t>(c)];
  const screw::RoundedUnitScrew& primary_action = r.row_actions[static_cast<std::size_t>(primary)];
  VerdictState state{"self-stress",
                     fmt::format("self-stress {} (action primary {} = 1; basis vector of the sparse QR of K^T)", j + 1,
                                 network::magnitude_name(coupling.name, {{}, primary_action.kind, primary_action.letter}, k)),
                     {}};
  double total = 0.0;
  for (const auto& [e, w] : wrench) total += frame.wrench_size(w);
  for (const auto& [e, w] : wrench) {
    const double share = total > 0 ? frame.wrench_size(w) / total : 0.0;
    if (share > kShareZero)
      state.participants.push_back({"coupling", model.couplings[static_cast<std::size_t>(e)].name, share, action_text(w, frame.scale())});
  }
  rank_participants(state.participants);
  return state;
}

// The motions beyond the declared inputs: the bodies that move in the sparse QR's motion basis,
// each with its mean share over the basis vectors and the twist of the vector it moves most in.
VerdictState beyond_state(const Model& model, const SparseNetworkResult& r, const Conditioning& frame, int beyond) {
  VerdictState state{"extra motion",
                     fmt::format("{} beyond the {} declared (bodies that move in the first {} of the FN = {} motions, "
                                 "basis vectors of the sparse QR of K)",
                                 counted(static_cast<std::size_t>(beyond), "motion", "motions"),
                                 counted(model.inputs.size(), "input", "inputs"), r.motion_basis.cols(), r.FN),
                     {}};
  const Index d = r.d;
  std::vector<double> share(model.bodies.size(), 0.0), best(model.bodies.size(), 0.0);
  std::vector<std::string> detail(model.bodies.size());
  for (Index j = 0; j < r.motion_basis.cols(); ++j) {
    std::vector<double> size(model.bodies.size(), 0.0);
    double total = 0.0;
    for (int b : r.moving_bodies) {
      const Index column = (b < r.ground ? b : b - 1) * d;
      size[static_cast<std::size_t>(b)] = frame.twist_size(r.motion_basis.col(j).segment(column, d));
      total += size[static_cast<std::size_t>(b)];
    }
    if (total <= 0) continue;
    for (int b : r.moving_bodies) {
      const auto ub = static_cast<std::size_t>(b);
      const double s = size[ub] / total;
      share[ub] += s / static_cast<double>(r.motion_basis.cols());
      if (s > best[ub]) {
        best[ub] = s;
        const Index column = (b < r.ground ? b : b - 1) * d;
        std::vector<double> coordinates(r.motion_basis.col(j).data() + column, r.motion_basis.col(j).data() + column + d);
        detail[ub] = motion_text(embed(coordinates, model.space), frame.scale());
      }
    }
  }
  for (int b : r.moving_bodies) {
    const auto ub = static_cast<std::size_t>(b);
    if (share[ub] > kShareZero) state.participants.push_back({"body", model.bodies[ub], share[ub], detail[ub]});
  }
  rank_participants(state.participants);
  return state;
}

// `listed` followed by every part of `kind` in `names` that is not in it yet (it takes part only
// in states beyond those listed), with `share`, ranked again.
void add_unlisted(std::vector<Participant>& listed, const std::string& kind, const std::vector<std::string>& names,
                  double share, const std::string& detail) {
  std::set<std::string> present;
  for (const auto& p : listed)
    if (p.kind == kind) present.insert(p.name);
  for (const auto& name : names)
    if (present.insert(name).second) listed.push_back({kind, name, share, detail});
  rank_participants(listed);
}

}  // namespace

Verdict sparse_network_verdict(const Model& model, const SparseNetworkResult& r, const Tolerances& tolerances) {
  return sparse_network_verdict(model, r, sparse_idle_spins(model, r, tolerances));
}

Verdict sparse_network_verdict(const Model& model, const SparseNetworkResult& r, const std::vector<IdleMotion>& idle) {
  Verdict v;
  const Conditioning frame{r.frame, &model.space};
  int idle_count = 0;
  for (const auto& i : idle) idle_count += i.count;
  idle_count = std::min(idle_count, r.FN);  // independent motions: at most FN (more is rounding)
  const int moving = r.FN - idle_count;  // motions that are not idle spins
  const int declared = static_cast<int>(model.inputs.size());
  const int intended = model.inputs.empty() ? moving : declared;
  const int beyond = std::max(0, moving - intended);
  const int lost = std::max(0, intended - moving);
  v.intended_motions = intended;
  v.intended_basis = model.inputs.empty() ? "none declared ('inputs:'): every motion but idle spins (FN less idle spins)" : "the declared 'inputs:'";
  v.extra_motions = idle_count + beyond;
  v.redundant_constraints = r.CN + lost;  // inputs beyond the motions fight each other
  v.exactly_constrained = v.extra_motions == 0 && v.redundant_constraints == 0;
  v.summary = summary_sentence(v.extra_motions, v.redundant_constraints, intended);
  // As the dense path says it; here the distance is the sparse factors' indicator (σ_min of the
  // better-conditioned kept block over σ_max), not a bound.
  note_near_rank_change(v, r.rank.distance(), r.FN > 0);

  // Extra motions: the idle spins (the first kSparseVerdictStates as states, every one under
  // `where`), then the motions beyond the declared inputs.
  std::vector<std::string> spinning;
  for (const auto& spin : idle) {
    const std::string& body = model.bodies[static_cast<std::size_t>(spin.body)];
    spinning.push_back(body);
    for (const auto& s : spin.screws) {
      if (static_cast<Index>(v.states.size()) >= kSparseVerdictStates) break;
      const std::string what = motion_text(embed(s, model.space), frame.scale());
      VerdictState state{"extra motion", idle_description(model, spin, what), {{"body", body, 1.0, what}}};
      std::vector<std::string> couplings;
      for (const auto& c : model.couplings)
        if (c.from == spin.body || c.to == spin.body) couplings.push_back(c.name);
      for (const auto& name : couplings)
        state.participants.push_back({"coupling", name, 1.0 / static_cast<double>(couplings.size()), "lets the body spin: " + what});
      v.states.push_back(std::move(state));
    }
  }
  if (beyond > 0) v.states.push_back(beyond_state(model, r, frame, beyond));

  // Self-stresses: the first kSparseVerdictStates basis vectors, the wrench of every coupling.
  std::vector<Index> first_row(model.couplings.size(), 0);
  for (std::size_t row = r.row_coupling.size(); row-- > 0;) first_row[static_cast<std::size_t>(r.row_coupling[row])] = static_cast<Index>(row);
  const Index stresses = std::min<Index>(r.stress_basis.cols(), kSparseVerdictStates);
  for (Index j = 0; j < stresses; ++j) v.states.push_back(self_stress_state(model, r, first_row, frame, j));

  v.motion_participants = strongest(v.states, "extra motion");
  add_unlisted(v.motion_participants, "body", spinning, 1.0, "spins idle (a state beyond those listed)");
  if (beyond > 0) {
    std::vector<std::string> bodies;
    for (int b : r.moving_bodies) bodies.push_back(model.bodies[static_cast<std::size_t>(b)]);
    add_unlisted(v.motion_participants, "body", bodies, 0.0, "moves in a motion beyond the basis vectors listed");
  }
  v.constraint_participants = strongest(v.states, "self-stress");
  std::vector<std::string> stressed;
  for (int c : r.stressed) stressed.push_back(model.couplings[static_cast<std::size_t>(c)].name);
  if (r.CN > 0) add_unlisted(v.constraint_participants, "coupling", stressed, 0.0, "carries a self-stress beyond those listed");

  if (v.exactly_constrained) {
    v.changes_verified = true;
    v.becomes = "unchanged: already exactly constrained";
    return v;
  }
  v.note = fmt::format("no change set searched on the sparse path ({}; each candidate change costs a re-analysis of "
                       "the whole network): analyse the couplings named under 'where' as a sub-network of at most {} "
                       "couplings for a verified change set, or run with --dense",
                       counted(model.couplings.size(), "coupling", "couplings"), kNetworkDesignSearchCouplings);
  if (lost > 0)
    v.note = fmt::format("{} declared for {}: drop {} (or add the motions they drive); ", counted(static_cast<std::size_t>(declared), "input is", "inputs are"),
                         counted(static_cast<std::size_t>(moving), "motion", "motions"), counted(static_cast<std::size_t>(lost), "input", "inputs")) +
             v.note;
  const auto listed_stresses = static_cast<int>(stresses);
  if (r.CN > listed_stresses)
    v.note += fmt::format("; the states list {} of the {} self-stresses, 'where' names every coupling that carries one",
                          listed_stresses, r.CN);
  return v;
}

}  // namespace kinestat::design
