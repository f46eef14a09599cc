// SPDX-License-Identifier: BSD-3-Clause
// The SPACAR reader: every supported keyword gives the model derived by hand (the expected
// values below come from the file's numbers and docs/formats.md, not from the program), the
// published mechanisms give the counts of seed 002 and of the YAML examples, and malformed
// files fail at the right line and column.

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>

#include "support/subspace_angles.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/spacar_reader.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace kinestat::io {
namespace {

using framework::CoordinateRole;
using framework::DeformationRole;
using framework::ElementType;
using framework::FrameworkModel;
using R = DeformationRole;
using C = CoordinateRole;

std::string data(const std::string& name) { return std::string(KINESTAT_SOURCE_DIR) + "/tests/importers/data/" + name; }
std::string spacar_example(const std::string& name) { return std::string(KINESTAT_SOURCE_DIR) + "/examples/spacar/" + name; }

std::size_t node(const FrameworkModel& m, const std::string& name) {
  for (std::size_t i = 0; i < m.nodes.size(); ++i)
    if (m.nodes[i].name == name) return i;
  ADD_FAILURE() << "no node " << name;
  return 0;
}

const framework::Element& element(const FrameworkModel& m, const std::string& name) {
  for (const auto& e : m.elements)
    if (e.name == name) return e;
  ADD_FAILURE() << "no element " << name;
  return m.elements.front();
}

std::string error_of(const std::string& text) {
  try {
    parse_spacar("bad.dat", text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SpacarReader, EveryKeywordGivesTheHandDerivedModel) {
  const SpacarImport imported = read_spacar(data("spacar-every-keyword.dat"));
  const FrameworkModel& m = imported.model;
  EXPECT_EQ(m.dimension, 3);
  // X nodes in file order, then the joint node for orientation node 16 at position 5.
  ASSERT_EQ(m.nodes.size(), 7u);
  const char* names[] = {"1", "3", "5", "7", "9", "11", "5r16"};
  for (std::size_t i = 0; i < 7; ++i) EXPECT_EQ(m.nodes[i].name, names[i]);
  EXPECT_EQ(m.nodes[node(m, "5")].position, Eigen::Vector3d(1, 1, 0));
  EXPECT_EQ(m.nodes[node(m, "5r16")].position, Eigen::Vector3d(1, 1, 0));
  for (const char* n : {"1", "3", "5", "7", "9", "11", "5r16"}) EXPECT_TRUE(m.nodes[node(m, n)].rotational) << n;

  ASSERT_EQ(m.elements.size(), 8u);
  const auto& e1 = element(m, "1");
  EXPECT_EQ(e1.type, ElementType::beam);
  EXPECT_EQ(e1.nodes, (std::vector<std::size_t>{node(m, "1"), node(m, "3")}));
  // x = (1, 0, 0), y as given = (0, 0, 1), z = x × y = (0, −1, 0).
  Eigen::Matrix3d f1;
  f1 << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  EXPECT_TRUE(e1.frame.isApprox(f1, 1e-15)) << e1.frame;
  EXPECT_EQ(e1.roles, (std::vector<R>{R::fixed, R::released, R::released, R::released, R::fixed, R::fixed}));

  const auto& e2 = element(m, "2");  // from (1,1,0) to (0,1,0): x = −e_x, default y = e_y, z = −e_z
  Eigen::Matrix3d f2;
  f2 << -1, 0, 0, 0, 1, 0, 0, 0, -1;
  EXPECT_TRUE(e2.frame.isApprox(f2, 1e-15)) << e2.frame;
  EXPECT_EQ(e2.roles, std::vector<R>(6, R::released));  // RLSE without numbers: every deformation

  const auto& e3 = element(m, "3");  // BEAMW: warping nodes skipped, y (0.5, 1, 0) made perpendicular to e_x
  EXPECT_EQ(e3.type, ElementType::beam);
  EXPECT_EQ(e3.nodes, (std::vector<std::size_t>{node(m, "3"), node(m, "11")}));
  EXPECT_TRUE(e3.frame.isApprox(Eigen::Matrix3d::Identity(), 1e-15)) << e3.frame;
  EXPECT_EQ(e3.roles, (std::vector<R>{R::fixed, R::fixed, R::fixed, R::fixed, R::fixed, R::independent}));

  EXPECT_EQ(element(m, "4").type, ElementType::truss);
  EXPECT_EQ(element(m, "4").roles, std::vector<R>{R::fixed});
  EXPECT_EQ(element(m, "5").roles, std::vector<R>{R::independent});
  EXPECT_EQ(element(m, "6").nodes, (std::vector<std::size_t>{node(m, "5"), node(m, "9")}));  // continuation line

  const auto& e7 = element(m, "7");  // from (1,1,0) to (0,0,1): x = (−1,−1,1)/√3, y = (−1,2,1)/√6
  EXPECT_EQ(e7.nodes, (std::vector<std::size_t>{node(m, "5r16"), node(m, "9")}));
  EXPECT_TRUE(e7.frame.col(0).isApprox(Eigen::Vector3d(-1, -1, 1) / std::sqrt(3.0), 1e-15));
  EXPECT_TRUE(e7.frame.col(1).isApprox(Eigen::Vector3d(-1, 2, 1) / std::sqrt(6.0), 1e-15));
  EXPECT_EQ(e7.roles, std::vector<R>(6, R::fixed));

  const auto& joint = element(m, "joint 5r16");  // positions together, orientations free
  EXPECT_EQ(joint.type, ElementType::rigid_body);
  EXPECT_EQ(joint.nodes, (std::vector<std::size_t>{node(m, "5"), node(m, "5r16")}));
  EXPECT_EQ(joint.roles, (std::vector<R>{R::fixed, R::fixed, R::fixed, R::released, R::released, R::released}));

  using Roles = std::array<C, 6>;
  const C d = C::dependent, f = C::fixed, i = C::independent;
  EXPECT_EQ(m.nodes[node(m, "1")].roles, (Roles{f, f, f, f, f, f}));       // FIX 1, FIX 2
  EXPECT_EQ(m.nodes[node(m, "7")].roles, (Roles{f, d, f, d, d, d}));       // FIX 7 1 3
  EXPECT_EQ(m.nodes[node(m, "5r16")].roles, (Roles{d, d, d, d, d, f}));    // FIX 16 4: λ3, rotation about z
  EXPECT_EQ(m.nodes[node(m, "9")].roles, (Roles{d, i, d, d, d, d}));       // INPUTX 9 2
  EXPECT_EQ(m.nodes[node(m, "5")].roles, (Roles{d, d, d, i, d, d}));       // INPUTX 6 2: λ1, rotation about x
  EXPECT_EQ(m.nodes[node(m, "11")].roles, (Roles{d, d, d, d, d, d}));      // FIX 12 1: λ0 ignored

  // One notice each: OUTLEVEL, λ0, FIX of a warping node, ESTIFF's shear terms (the card itself
  // and XM are read: docs/formats.md), BEAMW's warping; nothing else followed END.
  ASSERT_EQ(imported.notices.size(), 5u);
  EXPECT_NE(imported.notices[0].find("OUTLEVEL"), std::string::npos);
  EXPECT_NE(imported.notices[1].find("λ0"), std::string::npos);
  EXPECT_NE(imported.notices[2].find("FIX of warping node 13 ignored"), std::string::npos) << imported.notices[2];
  EXPECT_NE(imported.notices[3].find("ESTIFF of element 1: the shear-flexibility"), std::string::npos) << imported.notices[3];
  EXPECT_NE(imported.notices[4].find("BEAMW element(s) 3"), std::string::npos);
  ASSERT_EQ(m.masses.size(), 1u);  // XM 9 0.5
  EXPECT_EQ(m.nodes[m.masses[0].node].name, "9");
  EXPECT_EQ(m.masses[0].mass, 0.5);
}

TEST(SpacarReader, PlanarFourBarIsExactlyConstrained) {
  const FrameworkModel m = read_spacar(data("spacar-planar-four-bar.dat")).model;
  EXPECT_EQ(m.dimension, 2);
  ASSERT_EQ(m.nodes.size(), 6u);  // 1, 3, 5, 7 and the pins 3r10, 5r12
  EXPECT_EQ(m.nodes[4].name, "3r10");
  EXPECT_EQ(m.nodes[5].name, "5r12");
  EXPECT_EQ(element(m, "4").type, ElementType::truss);
  EXPECT_EQ(element(m, "4").roles, std::vector<R>{R::released});
  EXPECT_EQ(element(m, "joint 3r10").roles, (std::vector<R>{R::fixed, R::fixed, R::released}));
  const auto a = framework::analyse_framework(m);
  EXPECT_EQ(a.m, 13);
  EXPECT_EQ(a.n, 13);
  EXPECT_EQ(a.rank, 13);
  EXPECT_TRUE(a.exactly_constrained());
}

// D(c) has `rows` x `columns` and rank `rank`: n − rank mechanisms, m − rank self-stresses.
void expect_counts(const framework::FrameworkResult& a, Eigen::Index rows, Eigen::Index columns, Eigen::Index rank) {
  EXPECT_EQ(a.m, rows);
  EXPECT_EQ(a.n, columns);
  EXPECT_EQ(a.rank, rank);
  EXPECT_EQ(a.mechanisms, columns - rank);
  EXPECT_EQ(a.self_stresses, rows - rank);
}

// The rate of coordinate `slot` of node `name` in mode `mode` (0 when it is not dependent).
double mode_rate(const framework::FrameworkResult& a, const FrameworkModel& m, std::size_t mode, const std::string& name,
                 int slot) {
  const auto column = a.indexing.coordinate_of[node(m, name)][static_cast<std::size_t>(slot)];
  for (std::size_t c = 0; c < a.partition.dependent_coordinates.size(); ++c)
    if (a.partition.dependent_coordinates[c] == column) return a.modes[mode].velocities(static_cast<Eigen::Index>(c));
  return 0.0;
}

using kinestat::testing::principal_cosines;

using Names = std::map<std::string, std::string>;

// Modes (as rates of "node.slot") and stress states (as resultants of "element.deformation") of
// an analysis, rows in the order of `keys`, with node and element names mapped through `nodes`
// and `elements` (SPACAR numbers -> YAML names).
Eigen::MatrixXd mode_basis(const framework::FrameworkResult& a, const FrameworkModel& m, const std::vector<std::string>& keys,
                           const Names& nodes) {
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(keys.size()), static_cast<Eigen::Index>(a.modes.size()));
  for (std::size_t c = 0; c < a.partition.dependent_coordinates.size(); ++c) {
    const auto& ref = a.indexing.coordinates[static_cast<std::size_t>(a.partition.dependent_coordinates[c])];
    const std::string& name = m.nodes[ref.node].name;
    const std::string key = (nodes.empty() ? name : nodes.at(name)) + "." + framework::kSlotNames[static_cast<std::size_t>(ref.slot)];
    const auto row = std::find(keys.begin(), keys.end(), key) - keys.begin();
    EXPECT_LT(row, static_cast<long>(keys.size())) << key;
    for (std::size_t k = 0; k < a.modes.size(); ++k) basis(row, static_cast<Eigen::Index>(k)) = a.modes[k].velocities(static_cast<Eigen::Index>(c));
  }
  return basis;
}

Eigen::MatrixXd stress_basis(const framework::FrameworkResult& a, const FrameworkModel& m, const std::vector<std::string>& keys,
                             const Names& elements) {
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(keys.size()), static_cast<Eigen::Index>(a.stresses.size()));
  const auto rows = a.partition.jacobian_rows();
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const auto& ref = a.indexing.deformations[static_cast<std::size_t>(rows[r])];
    const std::string& name = m.elements[ref.element].name;
    const std::string key = (elements.empty() ? name : elements.at(name)) + "." + std::to_string(ref.deformation);
    const auto row = std::find(keys.begin(), keys.end(), key) - keys.begin();
    EXPECT_LT(row, static_cast<long>(keys.size())) << key;
    for (std::size_t k = 0; k < a.stresses.size(); ++k) basis(row, static_cast<Eigen::Index>(k)) = a.stresses[k].resultants(static_cast<Eigen::Index>(r));
  }
  return basis;
}

TEST(SpacarReader, PlanarFourBarJoinedByPlanarHingesHasOneMechanism) {
  FrameworkModel m = read_spacar(data("spacar-planar-hinged-four-bar.dat")).model;
  EXPECT_EQ(m.dimension, 2);
  ASSERT_EQ(m.nodes.size(), 6u);  // 1, 3, 5, 7 and the nodes of orientation 10 at 3 and 12 at 5
  // PLHINGE 4 joins orientation 4 (riding on node 3) and 10 (node 3r10): a rigid body whose
  // relative translations are free and whose relative rotation is deformation 1, released.
  const auto& h4 = element(m, "4");
  EXPECT_EQ(h4.type, ElementType::rigid_body);
  EXPECT_EQ(h4.nodes, (std::vector<std::size_t>{node(m, "3"), node(m, "3r10")}));
  EXPECT_EQ(h4.roles, (std::vector<R>{R::released, R::released, R::released}));
  EXPECT_EQ(element(m, "5").nodes, (std::vector<std::size_t>{node(m, "5"), node(m, "5r12")}));
  EXPECT_EQ(element(m, "5").roles, (std::vector<R>{R::released, R::released, R::released}));  // RLSE 5: all (one)
  EXPECT_EQ(element(m, "joint 3r10").roles, (std::vector<R>{R::fixed, R::fixed, R::released}));
  auto a = framework::analyse_framework(m);
  expect_counts(a, 13, 14, 13);  // one mechanism
  // With hinge 5 rigid (as DYNE 5 would keep it) coupler and rocker are one body: a triangle of
  // three bodies and three pins, exactly constrained.
  m.elements[3 + 1].roles[2] = R::fixed;
  a = framework::analyse_framework(m);
  expect_counts(a, 14, 14, 14);
}

TEST(SpacarReader, SpacarLightHingeAndPinBodyGiveAPendulum) {
  const SpacarImport imported = read_spacar(data("spacar-hinged-pendulum.dat"));
  FrameworkModel m = imported.model;
  EXPECT_EQ(m.dimension, 3);
  ASSERT_EQ(m.nodes.size(), 3u);  // the hinge's orientation 5 rides on position 4, which PINBODY carries
  const char* names[] = {"1", "4", "7"};
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(m.nodes[i].name, names[i]);
  const auto& hinge = element(m, "1");  // about z: deformation 1 is the relative rz, DYNE keeps it
  EXPECT_EQ(hinge.type, ElementType::rigid_body);
  EXPECT_EQ(hinge.nodes, (std::vector<std::size_t>{node(m, "1"), node(m, "4")}));
  EXPECT_EQ(hinge.roles, (std::vector<R>{R::released, R::released, R::released, R::fixed, R::fixed, R::fixed}));
  const auto& pin = element(m, "2");  // position 4 on the body of (1, 2); orientation free
  EXPECT_EQ(pin.nodes, (std::vector<std::size_t>{node(m, "1"), node(m, "4")}));
  EXPECT_EQ(pin.roles, (std::vector<R>{R::fixed, R::fixed, R::fixed, R::released, R::released, R::released}));
  EXPECT_EQ(element(m, "3").nodes, (std::vector<std::size_t>{node(m, "4"), node(m, "7")}));
  EXPECT_EQ(m.nodes[node(m, "1")].roles, (std::array<C, 6>{C::fixed, C::fixed, C::fixed, C::fixed, C::fixed, C::fixed}));
  auto a = framework::analyse_framework(m);
  expect_counts(a, 12, 12, 12);

  // Released, the hinge lets the arm swing about z: node 4 and 7 turn at the same rate w and
  // node 7, one unit out along x, moves along y at w x 1 (scaled by the characteristic length
  // L = 2/3: nodes at x = 0, 0, 1 around their centroid x = 1/3).
  m.elements[0].roles[5] = R::released;
  a = framework::analyse_framework(m);
  expect_counts(a, 11, 12, 11);
  ASSERT_EQ(a.modes.size(), 1u);
  const double w = mode_rate(a, m, 0, "7", 5);
  EXPECT_GT(std::abs(w), 0.1);
  EXPECT_NEAR(mode_rate(a, m, 0, "4", 5), w, 1e-12);
  EXPECT_NEAR(mode_rate(a, m, 0, "7", 1), w * 1.0 / (2.0 / 3.0), 1e-12);
  for (int slot : {0, 2, 3, 4}) EXPECT_NEAR(mode_rate(a, m, 0, "7", slot), 0.0, 1e-12) << slot;
  for (int slot : {0, 1, 2, 3, 4}) EXPECT_NEAR(mode_rate(a, m, 0, "4", slot), 0.0, 1e-12) << slot;
}

TEST(SpacarReader, TwoSpacarLightHingesInSeriesAreAUniversalJoint) {
  FrameworkModel m = read_spacar(data("spacar-universal-joint.dat")).model;
  ASSERT_EQ(m.nodes.size(), 4u);  // 1, 4, 7, 10: every orientation rides on its user node's position
  EXPECT_EQ(element(m, "1").nodes, (std::vector<std::size_t>{node(m, "1"), node(m, "4")}));
  EXPECT_EQ(element(m, "3").nodes, (std::vector<std::size_t>{node(m, "4"), node(m, "7")}));
  EXPECT_EQ(element(m, "3").roles, (std::vector<R>{R::released, R::released, R::released, R::fixed, R::fixed, R::fixed}));
  EXPECT_EQ(element(m, "4").nodes, (std::vector<std::size_t>{node(m, "4"), node(m, "7")}));
  auto a = framework::analyse_framework(m);
  expect_counts(a, 18, 18, 18);

  m.elements[0].roles[5] = R::released;  // hinge 1: rz
  m.elements[2].roles[4] = R::released;  // hinge 3: ry
  a = framework::analyse_framework(m);
  expect_counts(a, 16, 18, 16);  // two mechanisms
  // The two turns by hand (translations per characteristic length L = 0.75: nodes at x = 0, 0,
  // 0, 1 around x = 1/4): about z, the cross, the arm and its tip turn and the tip (1, 0, 0)
  // moves along +y; about y, the arm and its tip turn and the tip moves along -z.
  std::vector<std::string> keys;
  for (const char* n : {"4", "7", "10"})
    for (const char* slot : framework::kSlotNames) keys.push_back(std::string(n) + "." + slot);
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(keys.size()), 2);
  const auto at = [&](const std::string& key) { return std::find(keys.begin(), keys.end(), key) - keys.begin(); };
  for (const char* key : {"4.rz", "7.rz", "10.rz"}) expected(at(key), 0) = 1.0;
  expected(at("10.y"), 0) = 1.0 / 0.75;
  for (const char* key : {"7.ry", "10.ry"}) expected(at(key), 1) = 1.0;
  expected(at("10.z"), 1) = -1.0 / 0.75;
  const Eigen::VectorXd cosines = principal_cosines(mode_basis(a, m, keys, {}), expected);
  EXPECT_NEAR(cosines.minCoeff(), 1.0, 1e-12) << cosines.transpose();
}

// RBEAM e p rp q: q = p + R(rp)·(q0 − p0), three constraints (by hand, a link from (0,0,0)
// to (1,0,0)). Base position and orientation fixed: q is determined (0 motions, 0 redundant);
// q fixed as well: its 3 translations are held twice (3 redundant). Orientation rp free, base
// point fixed: the link turns about p, 3 rotations and q follows (3 motions); q fixed too: the
// rotations about y and z move q, the spin about the link's axis x does not, so of q's 3
// constraints on 3 rotations 2 are independent (1 motion, 1 redundant).
TEST(SpacarReader, RigidBeamHoldsItsEndOnTheBody) {
  const std::string link = "X 1 0 0 0\nX 3 1 0 0\nRBEAM 1 1 2 3 0 1 0\nFIX 1\n";
  const auto counts = [](const std::string& text) {
    const auto a = framework::analyse_framework(parse_spacar("rbeam.dat", text).model);
    return std::pair{a.mechanisms, a.self_stresses};
  };
  using Counts = std::pair<Eigen::Index, Eigen::Index>;
  EXPECT_EQ(counts(link + "FIX 2\nEND\n"), (Counts{0, 0}));
  EXPECT_EQ(counts(link + "FIX 2\nFIX 3\nEND\n"), (Counts{0, 3}));
  EXPECT_EQ(counts(link + "END\n"), (Counts{3, 0}));
  EXPECT_EQ(counts(link + "FIX 3\nEND\n"), (Counts{1, 1}));
  // q carrying an orientation of its own (the next link's rp): its rotations stay free of the
  // first link's, so a second link hangs from q by a spherical joint (3 motions more than the
  // first link's 0 when the base is held).
  const std::string chain = "X 1 0 0 0\nX 3 1 0 0\nX 5 2 0 0\nRBEAM 1 1 2 3\nRBEAM 2 3 4 5\nFIX 1\nFIX 2\n";
  EXPECT_EQ(counts(chain + "END\n"), (Counts{3, 0}));
  const SpacarImport imported = parse_spacar("rbeam.dat", chain + "END\n");
  const auto& first = element(imported.model, "1");
  EXPECT_EQ(first.type, ElementType::rigid_body);
  EXPECT_EQ(first.roles, (std::vector<R>{R::fixed, R::fixed, R::fixed, R::released, R::released, R::released}));
  EXPECT_EQ(element(imported.model, "2").roles, std::vector<R>(6, R::fixed));  // node 5: no orientation, held
}

TEST(SpacarReader, HingeToABareOrientationTakesItsNumberedPositionNode) {
  // Orientation node 8 is used only by hinge 3, on the ground's orientation 2, whose pin body
  // carries node 4 (already turned by node 5): SPACAR Light's numbering gives 8 to node 7.
  const FrameworkModel m = read_spacar(data("spacar-hinge-to-a-bare-orientation.dat")).model;
  ASSERT_EQ(m.nodes.size(), 4u);  // 1, 4, 7, 10: no jointed second orientation at node 4
  EXPECT_TRUE(m.nodes[node(m, "7")].rotational);
  EXPECT_FALSE(m.nodes[node(m, "10")].rotational);
  EXPECT_EQ(element(m, "3").nodes, (std::vector<std::size_t>{node(m, "1"), node(m, "7")}));
  const auto a = framework::analyse_framework(m);
  expect_counts(a, 9, 15, 9);  // by hand (the file's header): 6 mechanisms, no self-stress
  EXPECT_EQ(a.mechanisms, 6);
  EXPECT_EQ(a.self_stresses, 0);
}

TEST(SpacarReader, HingeBetweenTwoBeamsAboutY) {
  const FrameworkModel m = read_spacar(data("spacar-hinge-between-beams.dat")).model;
  ASSERT_EQ(m.nodes.size(), 4u);
  EXPECT_EQ(m.nodes[3].name, "3r6");
  const auto& hinge = element(m, "3");  // axis y: deformation 1 is ry (released), 2 and 3 rx, rz
  EXPECT_EQ(hinge.nodes, (std::vector<std::size_t>{node(m, "3"), node(m, "3r6")}));
  EXPECT_EQ(hinge.roles, (std::vector<R>{R::released, R::released, R::released, R::fixed, R::released, R::fixed}));
  EXPECT_EQ(element(m, "joint 3r6").roles,
            (std::vector<R>{R::fixed, R::fixed, R::fixed, R::released, R::released, R::released}));
  const auto a = framework::analyse_framework(m);
  expect_counts(a, 17, 18, 17);  // one mechanism
  ASSERT_EQ(a.modes.size(), 1u);
  // ω = (0, w, 0) about y through (1, 0, 0): node 5 at (2, 0, 0) moves with ω × (1, 0, 0) = (0, 0, −w).
  // L: nodes at x = 0, 1, 2, 1 around x = 1 -> L = 1.
  const double w = mode_rate(a, m, 0, "3r6", 4);
  EXPECT_GT(std::abs(w), 0.1);
  EXPECT_NEAR(mode_rate(a, m, 0, "5", 4), w, 1e-12);
  EXPECT_NEAR(mode_rate(a, m, 0, "5", 2), -w, 1e-12);
  for (const char* n : {"3", "5", "3r6"})
    for (int slot : {0, 1, 3, 5}) EXPECT_NEAR(mode_rate(a, m, 0, n, slot), 0.0, 1e-12) << n << " " << slot;
  EXPECT_NEAR(mode_rate(a, m, 0, "3", 4), 0.0, 1e-12);
}

TEST(SpacarReader, ParallelLeafSpringGuideHasOneSelfStress) {
  FrameworkModel m = read_spacar(spacar_example("parallel-leaf-spring-guide.dat")).model;
  auto a = framework::analyse_framework(m);
  EXPECT_EQ(a.m, 12);
  EXPECT_EQ(a.n, 11);
  EXPECT_EQ(a.rank, 11);
  EXPECT_EQ(a.mechanisms, 0);
  EXPECT_EQ(a.self_stresses, 1);
  // Without the prescribed x translation the guide moves along x.
  m.nodes[node(m, "5")].roles[0] = C::dependent;
  a = framework::analyse_framework(m);
  EXPECT_EQ(a.n, 12);
  EXPECT_EQ(a.rank, 11);
  EXPECT_EQ(a.mechanisms, 1);
  EXPECT_EQ(a.self_stresses, 1);
  ASSERT_EQ(a.modes.size(), 1u);
  // The mode is a pure translation along x of nodes 5 and 7: their x rates are equal and
  // every other rate is zero.
  const auto& v = a.modes[0].velocities;
  const auto x5 = a.indexing.coordinate_of[node(m, "5")][0], x7 = a.indexing.coordinate_of[node(m, "7")][0];
  Eigen::Index c5 = -1, c7 = -1;
  for (std::size_t c = 0; c < a.partition.dependent_coordinates.size(); ++c) {
    if (a.partition.dependent_coordinates[c] == x5) c5 = static_cast<Eigen::Index>(c);
    if (a.partition.dependent_coordinates[c] == x7) c7 = static_cast<Eigen::Index>(c);
  }
  ASSERT_GE(c5, 0);
  ASSERT_GE(c7, 0);
  EXPECT_NEAR(std::abs(v(c5)), std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(v(c5), v(c7), 1e-9);
}

TEST(SpacarReader, FoldedSheetGuideMatchesTheYamlExampleAndTheSeed) {
  const FrameworkModel dat = read_spacar(spacar_example("folded-sheet-guide-5.dat")).model;
  const FrameworkModel yaml =
      read_framework_model(YamlFile::load(std::string(KINESTAT_SOURCE_DIR) + "/examples/folded-sheet-guide-5.yaml"));
  const auto a = framework::analyse_framework(dat);
  const auto b = framework::analyse_framework(yaml);
  // Seed 002, Fig. 3(b): D(c) is 35 x 35 and non-singular.
  EXPECT_EQ(a.m, 35);
  EXPECT_EQ(a.n, 35);
  EXPECT_EQ(a.rank, 35);
  EXPECT_TRUE(a.exactly_constrained());
  EXPECT_EQ(a.m, b.m);
  EXPECT_EQ(a.n, b.n);
  EXPECT_EQ(a.rank, b.rank);
  // Same geometry: every sheet's frame equals the YAML one (local z along the fold line).
  ASSERT_EQ(dat.elements.size(), yaml.elements.size());
  for (std::size_t e = 0; e < dat.elements.size(); ++e) {
    EXPECT_TRUE(dat.elements[e].frame.isApprox(yaml.elements[e].frame, 1e-12)) << yaml.elements[e].name;
    EXPECT_EQ(dat.elements[e].roles, yaml.elements[e].roles) << yaml.elements[e].name;
  }
}

// The SPACAR model and the YAML model give the same counts and the same spaces of modes and of
// self-stresses (all principal angles zero), nodes and elements matched through the maps.
void expect_same_analysis(const FrameworkModel& dat, const FrameworkModel& yaml, const Names& nodes, const Names& elements,
                          const std::string& what) {
  SCOPED_TRACE(what);
  const auto a = framework::analyse_framework(dat);
  const auto b = framework::analyse_framework(yaml);
  EXPECT_EQ(a.m, b.m);
  EXPECT_EQ(a.n, b.n);
  EXPECT_EQ(a.rank, b.rank);
  ASSERT_EQ(a.mechanisms, b.mechanisms);
  ASSERT_EQ(a.self_stresses, b.self_stresses);
  std::vector<std::string> coordinate_keys, deformation_keys;
  for (const Eigen::Index c : b.partition.dependent_coordinates) {
    const auto& ref = b.indexing.coordinates[static_cast<std::size_t>(c)];
    coordinate_keys.push_back(yaml.nodes[ref.node].name + "." + framework::kSlotNames[static_cast<std::size_t>(ref.slot)]);
  }
  for (const Eigen::Index r : b.partition.jacobian_rows()) {
    const auto& ref = b.indexing.deformations[static_cast<std::size_t>(r)];
    deformation_keys.push_back(yaml.elements[ref.element].name + "." + std::to_string(ref.deformation));
  }
  if (a.mechanisms > 0) {
    const Eigen::VectorXd cosines = principal_cosines(mode_basis(a, dat, coordinate_keys, nodes), mode_basis(b, yaml, coordinate_keys, {}));
    EXPECT_NEAR(cosines.minCoeff(), 1.0, 1e-9) << cosines.transpose();
  }
  if (a.self_stresses > 0) {
    const Eigen::VectorXd cosines =
        principal_cosines(stress_basis(a, dat, deformation_keys, elements), stress_basis(b, yaml, deformation_keys, {}));
    EXPECT_NEAR(cosines.minCoeff(), 1.0, 1e-9) << cosines.transpose();
  }
}

FrameworkModel yaml_example(const std::string& name) {
  return read_framework_model(YamlFile::load(std::string(KINESTAT_SOURCE_DIR) + "/examples/" + name));
}

std::size_t element_index(const FrameworkModel& m, const std::string& name) {
  for (std::size_t i = 0; i < m.elements.size(); ++i)
    if (m.elements[i].name == name) return i;
  ADD_FAILURE() << "no element " << name;
  return 0;
}

TEST(SpacarPublished, LeafSpringGuideHasTheModesAndSelfStressesOfTheYamlExample) {
  FrameworkModel dat = read_spacar(spacar_example("parallel-leaf-spring-guide.dat")).model;
  FrameworkModel yaml = yaml_example("parallel-leaf-spring-guide.yaml");
  const Names nodes{{"1", "B1"}, {"3", "B2"}, {"5", "T1"}, {"7", "T2"}};
  const Names elements{{"1", "leaf1"}, {"2", "leaf2"}, {"3", "connector"}};
  // The header's hand count: 12 x 11, rank 11, one self-stress, no mode.
  expect_counts(framework::analyse_framework(yaml), 12, 11, 11);
  expect_same_analysis(dat, yaml, nodes, elements, "as written");
  // Without the prescribed x translation: one mode (along x) and the self-stress.
  dat.nodes[node(dat, "5")].roles[0] = C::dependent;
  yaml.nodes[node(yaml, "T1")].roles[0] = C::dependent;
  expect_same_analysis(dat, yaml, nodes, elements, "T1.x dependent");
}

TEST(SpacarPublished, FoldedSheetGuideHasTheModesAndSelfStressesOfTheYamlExample) {
  FrameworkModel dat = read_spacar(spacar_example("folded-sheet-guide-5.dat")).model;
  FrameworkModel yaml = yaml_example("folded-sheet-guide-5.yaml");
  const Names nodes{{"1", "C"},   {"3", "A1"},  {"5", "F1"},  {"7", "A2"},  {"9", "F2"}, {"11", "A3"},
                    {"13", "F3"}, {"15", "A4"}, {"17", "F4"}, {"19", "A5"}, {"21", "F5"}};
  Names elements;
  for (int f = 1; f <= 5; ++f)
    for (int s = 1; s <= 2; ++s) elements[std::to_string(2 * (f - 1) + s)] = fmt::format("f{}.s{}", f, s);
  expect_same_analysis(dat, yaml, nodes, elements, "as written (exactly constrained)");
  // Torsion of the second sheet of flexure 1 made rigid: 36 rows on 35 columns of a design
  // whose 35 rows had rank 35, so exactly one self-stress.
  FrameworkModel dat_stiff = dat, yaml_stiff = yaml;
  dat_stiff.elements[element_index(dat, "2")].roles[1] = R::fixed;
  yaml_stiff.elements[element_index(yaml, "f1.s2")].roles[1] = R::fixed;
  const auto a = framework::analyse_framework(yaml_stiff);
  EXPECT_EQ(a.self_stresses, 1);
  EXPECT_EQ(a.mechanisms, 0);
  expect_same_analysis(dat_stiff, yaml_stiff, nodes, elements, "f1.s2 torsion rigid");
  // C.z dependent: 35 rows of rank 35 on 36 columns, one mode (the guidance along z).
  dat.nodes[node(dat, "1")].roles[2] = C::dependent;
  yaml.nodes[node(yaml, "C")].roles[2] = C::dependent;
  EXPECT_EQ(framework::analyse_framework(yaml).mechanisms, 1);
  expect_same_analysis(dat, yaml, nodes, elements, "C.z dependent");
}

TEST(SpacarReader, ErrorsNameLineAndColumn) {
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 1 0 0\nBEAM 1 1 2 3\n"),
            "bad.dat:3:12: error: BEAM expects an element number, position and orientation node at p, then at q, and the "
            "local y direction; found 4 number(s)");
  EXPECT_EQ(error_of("X 1 0 0 0\nTRUSS 1 1 5\n"), "bad.dat:2:11: error: node 5 has no position: no X line defines it");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 1 1 0 0\n"), "bad.dat:2:3: error: node 1 is defined twice (first on line 1)");
  EXPECT_EQ(error_of("X 1 0 0 nan\n"), "bad.dat:1:9: error: expected a coordinate (a finite number), found 'nan'");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 1 0 0\nTRUSS 1 1 3\nCYLINDER 2 2 4\n"),
            "bad.dat:4:1: error: unsupported SPACAR keyword 'CYLINDER' in the kinematic part; kinestat reads X, BEAM, BEAMW, "
            "RBEAM, TRUSS, HINGE, PINBODY, PLBEAM, PLTRUSS, PLHINGE, DYNE, RLSE, INPUTE, FIX, INPUTX and DYNX up to END or HALT "
            "(no public description of this element's card was found: write the part with BEAM, TRUSS, HINGE and PINBODY "
            "elements, docs/formats.md)");
  // Hinges and pin bodies: what kinestat cannot express is refused, never guessed.
  const std::string beams = "X 1 0 0 0\nX 3 1 0 0\nX 5 2 0 0\nBEAM 1 1 2 3 4\nBEAM 2 3 6 5 7\n";
  EXPECT_EQ(error_of(beams + "HINGE 3 4 6 0 1\n"),
            "bad.dat:6:15: error: HINGE expects an element number, two orientation nodes and the hinge axis x y z; found 5 number(s)");
  EXPECT_EQ(error_of(beams + "HINGE 3 4 6 1 1 0\n"),
            "bad.dat:6:13: error: element 3: the hinge axis (1, 1, 0) is not along a global axis x, y or z; kinestat couples "
            "two orientations through their relative rotations about the global axes, so a hinge about another axis is not "
            "supported");
  EXPECT_EQ(error_of(beams + "HINGE 3 4 6 0 0 0\n"), "bad.dat:6:13: error: element 3: the hinge axis is the zero vector");
  // Two orientation nodes that nothing places (an orientation node hinged to a placed one
  // takes its position: the rigid catheter's hinge chains).
  EXPECT_EQ(error_of(beams + "HINGE 3 8 9 0 0 1\n"),
            "bad.dat:6:9: error: orientation node 8 of hinge 3 belongs to no position node: no BEAM, RBEAM or PINBODY uses "
            "it or a node hinged to it, and no X line defines node 7");
  EXPECT_EQ(error_of(beams + "HINGE 3 4 4 0 0 1\n"),
            "bad.dat:6:11: error: element 3 has the same orientation node 4 at both ends");
  EXPECT_EQ(error_of(beams + "HINGE 3 4 6 0 0 1\nRLSE 3 2\n"),
            "bad.dat:7:1: error: RLSE of HINGE 3: deformations 2 and 3 (the relative rotations about the two axes across the "
            "hinge axis) must be given together; which is which is not documented publicly");
  EXPECT_EQ(error_of(beams + "HINGE 3 4 6 0 0 1\nRLSE 3 4\n"),
            "bad.dat:7:8: error: element 3 (HINGE) has deformations 1 to 3, found 4");
  EXPECT_EQ(error_of(beams + "X 9 1 0 0\nPINBODY 3 3 4 9\n"),
            "bad.dat:7:15: error: PINBODY 3 carries position node 9, which no BEAM or HINGE gives an orientation node: "
            "kinestat cannot pin a node without one to a body");
  EXPECT_EQ(error_of(beams + "X 9 1 0 0\nBEAM 4 9 10 5 11\nPINBODY 3 3 4 9\nRLSE 3 1\n"),
            "bad.dat:9:1: error: RLSE of PINBODY 3: kinestat keeps a pin body rigid (its deformations are not documented "
            "publicly, so which is which is not known)");
  EXPECT_EQ(error_of("X 1 0 0\nX 3 1 0\nPLBEAM 1 1 2 3 4\nHINGE 2 2 4 0 0 1\n"),
            "bad.dat:4:1: error: HINGE mixes planar and spatial elements (PLBEAM on line 3, HINGE on line 4)");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 1 0 0\nTRUSS 1 1 3\nRLSE 1 2\n"),
            "bad.dat:4:8: error: element 1 (TRUSS) has deformations 1 to 1, found 2");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 1 0 0\nTRUSS 1 1 3\nRLSE 1 1\nDYNE 1 1\n"),
            "bad.dat:5:1: error: deformation 1 of element 1 is both RLSE and DYNE");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 1 0 0\nBEAM 1 1 2 3 4 1 0 0\n"),
            "bad.dat:3:1: error: element 1: the local y direction (1, 0, 0) is parallel to the element axis from node 1 to node 3");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 1 0 0\nBEAM 1 1 2 3 1\n"),
            "bad.dat:3:14: error: node 1 is a position node (defined by X on line 1); an orientation node is expected here");
  EXPECT_EQ(error_of("X 1 0 0\nX 3 1 0\nPLTRUSS 1 1 3\nTRUSS 2 1 3\n"),
            "bad.dat:4:1: error: TRUSS mixes planar and spatial elements (PLTRUSS on line 3, TRUSS on line 4)");
  EXPECT_EQ(error_of("1 2 3\n"), "bad.dat:1:1: error: expected a keyword (X, BEAM, ...) before numbers");
  EXPECT_EQ(error_of("X 1 0 0 0\nEND\n"),
            "bad.dat:2:1: error: no elements: a SPACAR model needs BEAM, BEAMW, RBEAM, TRUSS, HINGE, PINBODY, PLBEAM, PLTRUSS or "
            "PLHINGE lines");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 0 0 0\nTRUSS 1 1 3\n"), "bad.dat:3:11: error: zero-length element 1: nodes 1 and 3 coincide");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 1 0 0\nTRUSS 1 1 3\nFIX 7\n"),
            "bad.dat:4:5: error: FIX: node 7 is neither an X position node nor an orientation node of a beam");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 1 0 0\nTRUSS 1 1 3\nFIX 1 2\nINPUTX 1 2\n"),
            "bad.dat:5:1: error: coordinate y of node 1 is both fixed (FIX) and prescribed (INPUTX)");
  EXPECT_EQ(error_of("X 1 0 0 0\nX\x01 3\n"),
            "bad.dat:2:2: error: unexpected character: a SPACAR file holds ASCII keywords, numbers and '#' or '%' comments");
  EXPECT_EQ(error_of("X 1 0 0 0\nX 3 1 0 0\nTRUSS 0 1 3\n"),
            "bad.dat:3:7: error: expected an element number (a whole number from 1 to 100000000), found '0'");
}

}  // namespace
}  // namespace kinestat::io
