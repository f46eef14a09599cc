// SPDX-License-Identifier: BSD-3-Clause
// The framework model file: what it accepts, and one clear error with file, line and column for
// each kind of bad input.

#include <gtest/gtest.h>

#include <cmath>

#include "framework_test_support.hpp"

namespace kinestat::framework {
namespace {

using testing::parse_model;

// Parses `text` and returns the InputError's location and problem ("" when it parses).
struct Failure {
  int line = 0, column = 0;
  std::string problem;
};

Failure failure_of(const std::string& text) {
  try {
    parse_model(text);
  } catch (const io::InputError& error) {
    return {error.where().line, error.where().column, error.problem()};
  }
  return {};
}

const std::string kHead = "kinestat: 1\nkind: framework\n";

TEST(FrameworkReader, ReadsTheMinimumSchemaWithDefaults) {
  const FrameworkModel model = parse_model(kHead + R"(dimension: spatial
nodes: {A: [-1, -1, 0], E: [0, -1, 1]}
supports: {A: fixed}
elements:
  - {type: truss, nodes: [A, E]}
)");
  ASSERT_EQ(model.nodes.size(), 2u);
  EXPECT_FALSE(model.nodes[1].rotational);  // trusses only: translations
  EXPECT_EQ(model.nodes[0].roles[0], CoordinateRole::fixed);
  EXPECT_EQ(model.nodes[1].roles[0], CoordinateRole::dependent);  // default: dependent
  ASSERT_EQ(model.elements.size(), 1u);
  EXPECT_EQ(model.elements[0].name, "1");
  EXPECT_EQ(model.elements[0].roles, std::vector<DeformationRole>{DeformationRole::fixed});  // default: rigid
}

TEST(FrameworkReader, BeamReleasesGroupsOrientationAndIndependentDeformations) {
  const FrameworkModel model = parse_model(kHead + R"(nodes:
  A: [0, 0, 0]
  F: [0, 0, 2]
  C: {position: [1, 1, 1], orientation: [[0, 0, 1], [1, 0, 0], [0, 1, 0]]}
supports: {A: pinned}
independent: {F: [rz]}
elements:
  - {name: sheet, type: beam, nodes: [A, F], orientation: {y: [0, 3, 0]}, released: [torsion, bending_xy], independent: [bending_xy_q]}
  - {type: rigid_body, nodes: [F, C], released: [C.rx]}
)");
  const Element& sheet = model.elements[0];
  using R = DeformationRole;
  EXPECT_EQ(sheet.roles, (std::vector<R>{R::fixed, R::released, R::fixed, R::fixed, R::released, R::independent}));
  // Local x along A->F (global z), y as given (normalised), z = x × y = z × y = -x.
  EXPECT_TRUE(sheet.frame.col(0).isApprox(Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE(sheet.frame.col(1).isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_TRUE(sheet.frame.col(2).isApprox(-Eigen::Vector3d::UnitX()));
  EXPECT_TRUE(model.nodes[0].rotational);
  EXPECT_EQ(model.nodes[0].roles[2], CoordinateRole::fixed);      // pinned: translations fixed
  EXPECT_EQ(model.nodes[0].roles[3], CoordinateRole::dependent);  // rotations free
  EXPECT_EQ(model.nodes[1].roles[5], CoordinateRole::independent);
  EXPECT_EQ(model.elements[1].roles.size(), 6u);
  EXPECT_EQ(model.elements[1].roles[3], R::released);
  ASSERT_TRUE(model.nodes[2].triad.has_value());
}

TEST(FrameworkReader, PlanarBeamHasThreeDeformations) {
  const FrameworkModel model = parse_model(kHead + R"(dimension: planar
nodes: {A: [0, 0], B: [3, 4]}
supports: {A: fixed}
elements: [{type: beam, nodes: [A, B], released: [bending]}]
)");
  EXPECT_EQ(deformation_names(model, model.elements[0]), (std::vector<std::string>{"elongation", "bending_p", "bending_q"}));
  EXPECT_EQ(node_slots(2, model.nodes[1]), (std::vector<int>{0, 1, 5}));
  const FrameworkResult a = analyse_framework(model);
  // A cantilever with both bendings released and elongation rigid: B moves in 2 of its 3 coordinates.
  EXPECT_EQ(a.m, 1);
  EXPECT_EQ(a.n, 3);
  EXPECT_EQ(a.mechanisms, 2);
}

TEST(FrameworkReader, ElementNamesThatOnlyLookLikePositionsAreDistinct) {
  // "01" and "2.0" are not the positions "1" and "2": no clash.
  const FrameworkModel model = parse_model(kHead + R"(nodes: {A: [0, 0, 0], B: [1, 0, 0], C: [0, 1, 0]}
elements:
  - {name: "01", type: truss, nodes: [A, B]}
  - {type: truss, nodes: [B, C]}
  - {name: "2.0", type: truss, nodes: [A, C]}
)");
  ASSERT_EQ(model.elements.size(), 3u);
  EXPECT_EQ(model.elements[0].name, "01");
  EXPECT_EQ(model.elements[1].name, "2");
  EXPECT_EQ(model.elements[2].name, "2.0");
}

struct BadInput {
  const char* name;
  std::string body;  // after the common head
  int line, column;
  const char* problem;  // a fragment of the message
};

class FrameworkReaderRejects : public ::testing::TestWithParam<BadInput> {};

TEST_P(FrameworkReaderRejects, WithPositionAndReason) {
  const BadInput& bad = GetParam();
  const Failure f = failure_of(kHead + bad.body);
  EXPECT_EQ(f.line, bad.line) << f.problem;
  EXPECT_EQ(f.column, bad.column) << f.problem;
  EXPECT_NE(f.problem.find(bad.problem), std::string::npos) << f.problem;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, FrameworkReaderRejects,
    ::testing::Values(
        BadInput{"zero_length", "nodes: {A: [0, 0, 0], B: [0, 0, 0]}\nelements:\n  - {type: truss, nodes: [A, B]}\n", 5, 26,
                 "zero-length element '1'"},
        BadInput{"unknown_node", "nodes: {A: [0, 0, 0], B: [1, 0, 0]}\nelements:\n  - {type: truss, nodes: [A, X]}\n", 5, 30,
                 "unknown node 'X'"},
        BadInput{"fixed_and_independent",
                 "nodes: {A: [0, 0, 0], B: [1, 0, 0]}\nsupports: {B: [x, y]}\nindependent: {B: [z, x]}\n"
                 "elements:\n  - {type: truss, nodes: [A, B]}\n",
                 5, 22, "coordinate 'B.x' is both fixed"},
        BadInput{"release_not_in_element",
                 "nodes: {A: [0, 0, 0], B: [1, 0, 0]}\nelements:\n  - {type: truss, nodes: [A, B], released: [torsion]}\n", 5,
                 45, "has no deformation 'torsion'"},
        BadInput{"triad_not_orthonormal",
                 "nodes:\n  A: {position: [0, 0, 0], orientation: [[1, 0, 0], [0, 1, 0.1], [0, 0, 1]]}\n  B: [1, 0, 0]\n"
                 "elements:\n  - {type: beam, nodes: [A, B]}\n",
                 4, 41, "not orthonormal"},
        BadInput{"element_axis_not_perpendicular",
                 "nodes: {A: [0, 0, 0], B: [1, 0, 0]}\nelements:\n  - {type: beam, nodes: [A, B], orientation: {y: [1, 1, 0]}}\n",
                 5, 50, "must be perpendicular"},
        BadInput{"left_handed", "nodes:\n  A: {position: [0, 0, 0], orientation: [[1, 0, 0], [0, 0, 1], [0, 1, 0]]}\n  B: [1, 0, 0]\n"
                                "elements:\n  - {type: beam, nodes: [A, B]}\n",
                 4, 41, "left-handed"},
        BadInput{"duplicate_node", "nodes: {A: [0, 0, 0], A: [1, 0, 0]}\nelements: []\n", 3, 23, "duplicate node name 'A'"},
        // Element names, given or by position ("1", "2", ...), are unique; the error is at the
        // element that repeats a name (its flow map starts at column 5).
        BadInput{"duplicate_given_element_name",
                 "nodes: {A: [0, 0, 0], B: [1, 0, 0], C: [0, 1, 0]}\nelements:\n  - {name: a, type: truss, nodes: [A, B]}\n"
                 "  - {name: a, type: truss, nodes: [B, C]}\n",
                 6, 5, "duplicate element name 'a'"},
        BadInput{"given_name_repeats_a_position",
                 "nodes: {A: [0, 0, 0], B: [1, 0, 0], C: [0, 1, 0]}\nelements:\n  - {type: truss, nodes: [A, B]}\n"
                 "  - {name: 1, type: truss, nodes: [B, C]}\n",
                 6, 5, "duplicate element name '1'"},
        BadInput{"position_repeats_a_given_name",
                 "nodes: {A: [0, 0, 0], B: [1, 0, 0], C: [0, 1, 0]}\nelements:\n  - {name: 3, type: truss, nodes: [A, B]}\n"
                 "  - {type: truss, nodes: [B, C]}\n  - {type: truss, nodes: [A, C]}\n",
                 7, 5, "duplicate element name '3'"},
        BadInput{"nan_position", "nodes: {A: [0, .nan, 0], B: [1, 0, 0]}\nelements: []\n", 3, 16, "finite number"},
        BadInput{"rotation_of_truss_node",
                 "nodes: {A: [0, 0, 0], B: [1, 0, 0]}\nsupports: {A: [rz]}\nelements:\n  - {type: truss, nodes: [A, B]}\n", 4,
                 16, "no rotational coordinate 'rz'"},
        BadInput{"wrong_position_length", "dimension: planar\nnodes: {A: [0, 0, 0]}\nelements: []\n", 4, 12, "must have 2 numbers"},
        BadInput{"unknown_type", "nodes: {A: [0, 0, 0], B: [1, 0, 0]}\nelements:\n  - {type: spring, nodes: [A, B]}\n", 5, 12,
                 "unknown element type 'spring'"},
        BadInput{"unknown_key", "nodes: {A: [0, 0, 0]}\nelemets: []\n", 4, 1, "unknown key 'elemets'"},
        BadInput{"node_triad_not_along_beam",
                 "nodes:\n  A: {position: [0, 0, 0], orientation: [[0, 1, 0], [-1, 0, 0], [0, 0, 1]]}\n  B: [1, 0, 0]\n"
                 "elements:\n  - {type: beam, nodes: [A, B]}\n",
                 7, 25, "x axis must point along element '1'"}),
    [](const ::testing::TestParamInfo<BadInput>& param) { return std::string(param.param.name); });

}  // namespace
}  // namespace kinestat::framework
