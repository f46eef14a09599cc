// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Position analysis of a planar mechanism group by group (issue 13, item 3; seed 004's next
// step): the structural groups are solved in their order of formation, each from the poses of
// the bodies solved before it. Driving links and the dyads RRR, RRP (PRR), RPR and PRP have
// closed forms (circle–circle, circle–line, line–line); every other group (triads, RPP dyads,
// ...) is solved by Newton's method on its own closure equations from the previous configuration.
//
// Poses are relative to the configuration written in the model file: a body at pose (x, y, θ)
// has moved its material point p (file coordinates, length units, xy-plane) to R(θ) p + (x, y).
// Every body is at the identity pose in the file's configuration.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "kinestat/error.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/structure/decomposition.hpp"
#include "kinestat/structure/structure_model.hpp"

namespace kinestat::kinematics {

/// Pose of a planar body relative to the file's configuration: rotation `angle` (rad,
/// counter-clockwise about +z) about the origin, then translation (x, y) (length units).
struct Pose {
  double x = 0.0;
  double y = 0.0;
  double angle = 0.0;
};

/// How a group is solved.
enum class GroupMethod {
  driving_link,  ///< one body driven by its input coupling: closed form
  closed_form,   ///< a dyad RRR, RRP, PRR, RPR or PRP: circle–circle, circle–line or line–line
  newton,        ///< Newton's method on the group's closure equations
};

/// The JSON spelling: "driving_link", "closed_form", "newton".
const char* group_method_name(GroupMethod method);

/// One structural group ready to be solved: which bodies and couplings, and the assembly branch
/// of the file's configuration.
struct GroupPlan {
  int number = 0;                 ///< 1-based, in order of formation (structure::StructuralGroup::number)
  std::vector<int> bodies;        ///< network body indices
  std::vector<int> couplings;     ///< network coupling indices counted: internal, and to bodies solved before
  std::string type;               ///< "driving link R", "dyad RRR", ..., "group of 4 bodies and 6 couplings"
  GroupMethod method = GroupMethod::newton;
  /// Dyads: the couplings in chain order J1 (to a solved body), J2 (internal), J3 (to a solved
  /// body), with J1 revolute when exactly one of J1, J3 is prismatic.
  std::vector<int> chain;
  std::vector<std::size_t> after;  ///< indices into PositionPlan::groups of the groups it is placed on
  /// Closed forms with two solutions: +1 or −1, the side of the branch indicator in the file's
  /// configuration (see `branch`); 0 for a single solution or Newton.
  int branch_sign = 0;
  /// The branch in words: which sign of which quantity the file's configuration has and every
  /// solution keeps.
  std::string branch;
};

/// The groups of a mechanism in their order of formation, with its drivers.
struct PositionPlan {
  int frame = 0;                 ///< network body index of the frame (the ground)
  std::vector<int> drivers;      ///< coupling index of each input, in the order of network::Model::inputs
  std::vector<GroupPlan> groups;
  double length = 1.0;           ///< characteristic length: RMS distance of the coupling points from their centroid
};

/// A model position solving cannot take (not planar, a coupling of another type, inputs that do
/// not decompose it). `coupling()` is the index of the coupling concerned, or −1.
class PositionModelError : public Error {
 public:
  explicit PositionModelError(const std::string& what, int coupling = -1) : Error(what), coupling_(coupling) {}
  int coupling() const noexcept { return coupling_; }

 private:
  int coupling_;
};

/// Builds the plan of `model` (planar; revolute and prismatic couplings only; `model.inputs`
/// the driving couplings, each once) from its structural decomposition `decomposition` of
/// `structure` (io::structure_of_network of the same model, same body names). Throws
/// kinestat::Error when the model is not planar, has another coupling type, or the
/// decomposition is incomplete.
PositionPlan plan_positions(const network::Model& model, const structure::StructureModel& structure,
                            const structure::StructureResult& decomposition);

/// Whether a group could be placed.
enum class AssemblyStatus {
  assembled,      ///< placed, away from a singular position
  singular,       ///< placed at a singular position: two branches meet (discriminant zero within tolerance)
  not_assembled,  ///< no real solution (discriminant < 0), parallel slide axes, or Newton did not converge
  not_reached,    ///< a group it depends on was not assembled
};

/// The JSON spelling: "assembled", "singular", "not_assembled", "not_reached".
const char* assembly_status_name(AssemblyStatus status);

/// The outcome for one group at one set of input values.
struct GroupSolution {
  AssemblyStatus status = AssemblyStatus::not_reached;
  /// Closed forms: the discriminant (circle–circle h², circle–line h², RPR 1 − (c/d)²,
  /// line–line sine of the angle of the axes) relative to its scale; Newton: the final
  /// residual relative to the characteristic length.
  double discriminant = 0.0;
  int iterations = 0;   ///< Newton iterations (0 for closed forms)
  std::string reason;   ///< why not assembled or singular, in words; empty when assembled
};

/// The positions of all bodies at one set of input values.
struct PositionResult {
  std::vector<Pose> poses;              ///< per network body; unchanged from the start for unsolved bodies
  std::vector<GroupSolution> groups;    ///< per plan group
  bool assembled = false;               ///< every group assembled (or singular)
  std::optional<std::size_t> failed_group;  ///< index into plan.groups of the first group not assembled
  /// Largest closure residual of all couplings and inputs (lengths over the characteristic
  /// length, angles in rad) when assembled.
  double max_residual = 0.0;
};

/// Solves the positions of `model` at input values `values` (one per plan.drivers: rad for a
/// revolute, the rotation of the second body of `between` relative to the first, counter-
/// clockwise; length units for a prismatic, the slide of the second body relative to the first
/// along the axis), group by group. Newton groups start from `start` (poses per body; empty:
/// the file's configuration). Pure: no input is changed.
PositionResult solve_positions(const network::Model& model, const PositionPlan& plan, const std::vector<double>& values,
                               const std::vector<Pose>& start = {});

/// The value of coupling `coupling` at `poses`: relative rotation (rad) for a revolute, slide
/// (length units) for a prismatic, both of the second body of `between` relative to the first.
double coupling_value(const network::Model& model, const std::vector<Pose>& poses, int coupling);

/// Where the point of coupling `coupling` (its `point`, on the second body of `between`) is at
/// `poses`: global frame, length units.
std::array<double, 2> coupling_point(const network::Model& model, const std::vector<Pose>& poses, int coupling);

}  // namespace kinestat::kinematics
