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
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/framework/framework_model.hpp"
#include "kinestat/network/model.hpp"
#include "kinestat/network/network_result.hpp"
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
  bool fixed = false;  ///< supported (frameworks) or part of the ground body
};

/// A line between two nodes: a truss or beam, one node of a rigid body to its reference
/// node, a link of a network body, or a pair of a structure model.
struct SceneElement {
  std::string name;
  std::string type;  ///< "truss", "beam", "rigid", "link", "pair"
  int a = 0;
  int b = 0;
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

/// A kinematic mode: the velocity of every node (same order as Scene::nodes), in the model's
/// length unit per unit rate of the mode.
struct SceneMode {
  std::string label;
  std::vector<Eigen::Vector3d> velocity;
};

/// A self-stress state: one value per element (normal force / elongation resultant), signed:
/// positive tension, negative compression. Elements without a value have 0.
struct SceneStress {
  std::string label;
  std::vector<double> value;
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
  std::string kind;  ///< "network", "framework" or "structure"
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
  /// The verdict every picture leads with (design layer; filled by whoever loads the model).
  std::optional<design::Verdict> verdict;
  /// The model's length unit (`units:`), empty when the file names none.
  std::string units;
};

/// Above this many elements (or nodes) the writers switch to a lighter drawing: no glyphs,
/// no labels, elements merged into one path / line set.
inline constexpr std::size_t kLargeSceneElements = 20000;

Scene network_scene(const network::Model& model, const network::NetworkResult& result);
Scene framework_scene(const framework::FrameworkModel& model, const framework::FrameworkAnalysis& analysis);
Scene structure_scene(const structure::StructureModel& model, const structure::Decomposition& decomposition);

/// Fixed-precision text of a number for drawings and JSON: at most `digits` decimals,
/// trailing zeros dropped, "-0" written as "0". Deterministic across platforms.
std::string fixed(double value, int digits = 3);

}  // namespace kinestat::report
