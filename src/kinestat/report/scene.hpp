// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene: what the pictures of a model show, as plain data built from a model and its
// result — node positions, elements, coupling glyphs, modes as nodal velocities, stress
// values per element, the coupling graph and a summary. The SVG and HTML writers both draw
// from it; no analysis happens here.

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

#include "kinestat/design/verdict.hpp"
#include "kinestat/framework/analysed_cost.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/framework_model.hpp"
#include "kinestat/framework/two_way_trace.hpp"
#include "kinestat/io/model_kind.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/network/network_result.hpp"
#include "kinestat/network/sparse_network.hpp"
#include "kinestat/structure/decomposition.hpp"
#include "kinestat/structure/structure_model.hpp"

namespace kinestat::report {

/// One line of the summary: a label and its value as text, e.g. {"FN", "1"}.
struct SceneFact {
  std::string key;
  std::string value;
};

/// A point of the drawing: a framework node, or for networks a body's centre or a body's end
/// at one of its couplings (each body is drawn as a star of links from its centre).
struct SceneNode {
  std::string name;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  int body = -1;       ///< networks and structures: the body the node belongs to
  bool fixed = false;  ///< all translations supported (frameworks) or part of the ground body
  /// Frameworks: "fixed" (translations and rotations held), "pinned" (translations held,
  /// rotations free), "roller" (some translations held) or "" (free).
  std::string support;
  /// Rollers: the free translation directions (unit vectors along global axes).
  std::vector<Eigen::Vector3d> free_directions;
};

/// A line between two nodes: a truss or beam, one node of a rigid body to its reference
/// node, a link of a network body, or a pair of a structure model.
struct SceneElement {
  std::string name;
  std::string type;  ///< "truss", "beam", "rigid", "link", "pair"
  int a = 0;
  int b = 0;
  bool label = true;  ///< name this line in pictures (a rigid body or body star is named once)
  /// Beams the model makes sheets (leaf springs): in-plane bending and elongation held, torsion
  /// and out-of-plane bending free. The unit direction across the sheet, in its plane; the
  /// model gives no width, so pictures draw the sheet kSheetWidth times its length wide.
  std::optional<Eigen::Vector3d> sheet_across;
};

/// Width of a drawn sheet as a share of its length (the model has no width).
inline constexpr double kSheetWidth = 0.3;

/// A screw drawn as its axis (networks): a wrench a coupling transmits in a self-stress, or the
/// twist of a body in a mode. `point` is the point of the axis nearest to `anchor`.
struct SceneScrew {
  std::string name;  ///< the coupling or body
  Eigen::Vector3d anchor = Eigen::Vector3d::Zero();     ///< coupling point or body centre
  Eigen::Vector3d point = Eigen::Vector3d::Zero();      ///< on the axis
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ(); ///< unit: force (wrench) or ω (twist)
  /// |force| (wrench) or |ω| (twist); for a pure couple or translation |moment| or |v|.
  double magnitude = 0.0;
  double pitch = 0.0;      ///< moment along the axis per force, or v along the axis per ω (length)
  bool pure = false;       ///< infinite pitch: a pure couple / translation along `direction`
};

/// A coupling of a network drawn at its point: type, axes and its unit screws.
struct SceneGlyph {
  std::string name;
  std::string type;  ///< coupling type name, e.g. "revolute"
  int from = 0;      ///< bodies
  int to = 0;
  int f = 0;
  int c = 0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector3d> axis, axis2, normal;
  std::vector<std::vector<double>> motions;  ///< unit motions, d coordinates each (axis formation)
  std::vector<std::vector<double>> actions;  ///< unit actions, d coordinates each (ray formation)
};

/// A mode's finite motion as traced (frameworks of bars, issue 13): node positions at points of
/// the path, from the far end of the backward side (−mode) through the model's configuration
/// to the far end of the forward side (+mode).
struct SceneTrace {
  /// Per point: the position of every node (same order as Scene::nodes), global frame, length units.
  std::vector<std::vector<Eigen::Vector3d>> positions;
  /// Per point: the signed arc length from the model's configuration (length units; negative
  /// on the backward side), increasing.
  std::vector<double> arc;
  std::size_t start = 0;      ///< the point that is the model's configuration
  double max_residual = 0.0;  ///< largest closure residual of the points, relative to the characteristic length
  /// Why a side stops short of the amplitude asked for (the corrector lost closure), or empty.
  std::string note;
};

/// A kinematic mode: the velocity of every node (same order as Scene::nodes), in the model's
/// length unit per unit rate of the mode.
struct SceneMode {
  std::string label;
  std::vector<Eigen::Vector3d> velocity;
  std::vector<std::string> moving;  ///< coordinates (frameworks) or motion magnitudes (networks) that move
  std::vector<SceneScrew> twists;   ///< networks: the twist of every moving body relative to the ground
  /// Frameworks: the traced finite motion the report animates instead of the velocities.
  std::optional<SceneTrace> trace;
  /// Frameworks without `trace`: why the animation is first order only, e.g. "blocked at second
  /// order by a self-stress". Empty for networks.
  std::string first_order_reason;
  /// "" a kinematic mode; "vibration" an eigenmode of small free vibration (issue 38: models
  /// with elastic data and mass), its frequency in the label.
  std::string kind;
};

/// One generalised stress resultant of a self-stress (the element x deformation table).
struct SceneResultant {
  std::string element;
  std::string deformation;
  double value = 0.0;
};

/// A self-stress state, with the sign the analysis decided (never re-decided here). Per
/// element: the dominant generalised stress resultant (largest magnitude among the element's
/// resultants) and its kind: "elongation" (normal force; positive tension, negative
/// compression), "torsion", "bending", "rigid" (a rigid body's internal constraint force) or
/// "" (none). Networks: the wrench every coupling transmits instead.
struct SceneStress {
  std::string label;
  std::vector<double> value;
  std::vector<std::string> kind;
  std::vector<SceneResultant> resultants;  ///< frameworks: every non-zero resultant, in row order
  std::vector<SceneScrew> wrenches;        ///< networks: couplings that transmit an action
  /// "" for a self-stress state (unit norm, no unit); otherwise the unit of `value` and of the
  /// resultants: the stress a misfit locks in (issue 38), e.g. "N/mm^2".
  std::string unit;
};

/// An edge of the coupling graph (networks) or of the pair graph (structures).
struct GraphEdge {
  std::string name;
  int from = 0;
  int to = 0;
  bool branch = true;  ///< tree branch (thick) or chord (thin)
  int f = 0;           ///< freedoms: edges in series in the motion graph
  int c = 0;           ///< constraints: edges in parallel in the action graph
  std::vector<std::string> motion_names;  ///< names of the f motion magnitudes (networks)
  std::vector<std::string> action_names;  ///< names of the c action magnitudes (networks)
};

/// Motion system of a pair of bodies (networks): the unit screws spanning it.
struct ScenePair {
  int body_i = 0;
  int body_j = 0;
  int fij = 0;
  std::vector<std::vector<double>> motions;  ///< one screw per motion primary that appears
};

struct Scene {
  io::ModelKind kind = io::ModelKind::network;
  std::string name;
  int dimension = 3;  ///< 2: everything lies in the xy-plane; 3: spatial
  int screw_dimension = 6;
  std::vector<SceneFact> summary;
  std::vector<std::string> bodies;  ///< networks and structures
  int ground = 0;
  std::vector<SceneNode> nodes;
  std::vector<SceneElement> elements;
  std::vector<SceneGlyph> glyphs;
  std::vector<SceneMode> modes;
  std::vector<SceneStress> stresses;
  std::vector<GraphEdge> edges;
  Eigen::MatrixXi B, Q;  ///< circuits and cutsets over `edges` (networks)
  std::vector<ScenePair> pairs;
  /// Structures: the structural group of each body (0: frame or none).
  std::vector<int> group_of;
  /// The model had more elements than a picture can show one by one.
  bool large = false;
  /// A network analysed in sparse body-twist form (above network::kDenseNetworkLimit
  /// couplings): no circuits, cutsets (B, Q empty), magnitude names or pair systems; the tree
  /// drawn is the breadth-first one from the ground; modes and self-stresses are the first
  /// basis vectors of the sparse QR, and a mode's `moving` names couplings.
  bool sparse = false;
  /// The model's number of modes and of self-stresses when the scene holds only the first
  /// ones (sparse networks); 0 when `modes` and `stresses` are all of them.
  std::size_t mode_total = 0, stress_total = 0;
  /// The verdict every picture leads with (design layer; filled by whoever loads the model).
  std::optional<design::Verdict> verdict;
  /// The model's length unit (`units:`), empty when the file names none ("model units").
  std::string units;
};

/// The unit text of a scene: its `units`, or "model units" when none was given.
std::string length_unit(const Scene& scene);

/// Above this many elements (or nodes) the writers switch to a lighter drawing: no glyphs,
/// no labels, elements merged into one path / line set.
inline constexpr std::size_t kLargeSceneElements = 20000;

/// The scene of a network from its dense (Davies) analysis: every motion and action primary.
Scene network_scene(const network::Model& model, const network::NetworkResult& result);
/// The scene of a network from its sparse analysis (network::analyse_network_sparse with
/// vectors): the bodies, couplings and their unit actions, the first basis vectors of the
/// motions (body twists relative to the ground) and of the self-stresses (the wrench every
/// coupling transmits), each scaled so that its primary is 1; user frame and length unit.
/// Linear in the network's size, for networks of any size.
Scene sparse_network_scene(const network::Model& model, const network::SparseNetworkResult& result);
/// The scene of a framework. `traces` (framework::animation_traces, one entry per mode, or
/// empty) gives the modes whose finite motion was traced both ways; every other mode gets the
/// reason it is drawn to first order only.
Scene framework_scene(const framework::FrameworkModel& model, const framework::FrameworkResult& analysis,
                      const std::vector<std::optional<framework::TwoWayTrace>>& traces = {});
/// Adds the cost of over-constraint of a framework with elastic data (issue 38, item 5) to its
/// scene: a stress entry colouring every element by the peak stress the worst misfit locks in
/// (signed by the axial force when the element carries no moment; the worst element named in
/// the label with its stress and unit), the lowest eigenmodes of free vibration as modes (kind
/// "vibration", each node's translation in the mode shape, largest 1, frequency in Hz in the
/// label) and two summary lines. A cost not computed adds one summary line saying why.
void add_framework_cost(Scene& scene, const framework::FrameworkModel& model, const framework::AnalysedCost& cost);

Scene structure_scene(const structure::StructureModel& model, const structure::StructureResult& decomposition);

/// Fixed-precision text of a number for drawings and JSON: at most `digits` decimals,
/// trailing zeros dropped, "-0" written as "0". Deterministic across platforms.
std::string fixed(double value, int digits = 3);

}  // namespace kinestat::report
