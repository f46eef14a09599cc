// SPDX-License-Identifier: BSD-3-Clause
// Published mechanisms: every expected value comes from the literature cited in the example
// file's header (Davies' seed 000; Bennett 1903; Hunt 1978; Phillips; Merlet), from a
// Grübler-Kutzbach count or from Davies' identities, never from the program's output.

#include <gtest/gtest.h>

#include <algorithm>

#include "kinestat/network/analyse_network.hpp"
#include "model_transforms.hpp"

namespace kinestat::mechanisms_test {
namespace {

using network::Arithmetic;
using network::NetworkClass;

network::NetworkResult analyse(const network::Model& model, Arithmetic arithmetic = Arithmetic::automatic) {
  network::AnalysisOptions options;
  options.arithmetic = arithmetic;
  return network::analyse_network(model, options);
}

// Davies' identities (seed 000, eqs 7, 8, 16) and agreement of the dual methods.
void expect_consistent(const network::NetworkResult& r) {
  EXPECT_TRUE(r.identities_hold);
  EXPECT_EQ(r.FN - r.CN, r.F - r.d * r.l);
  EXPECT_EQ(r.CN - r.FN, r.C - r.d * r.k);
  EXPECT_TRUE(r.motion_methods_agree);
  EXPECT_TRUE(r.action_methods_agree);
}

TEST(SingleCircuitTwoSpheres, SeedSections21And22) {
  const auto model = load_example("single-circuit-two-spheres.yaml");
  const auto r = analyse(model);
  EXPECT_TRUE(r.exact);
  EXPECT_EQ(r.d, 6);
  EXPECT_EQ(r.F, 6);
  EXPECT_EQ(r.C, 6);
  EXPECT_EQ(r.l, 1);
  EXPECT_EQ(r.k, 1);
  EXPECT_EQ(r.FN, 1);
  EXPECT_EQ(r.CN, 1);
  EXPECT_EQ(r.classification, NetworkClass::overconstrained_chain);
  expect_consistent(r);

  // Section 2.1: all motion magnitudes zero except ta and tb; the coupling orientations of
  // the file (both from body 1 to body 2) make the circuit law read ta - tb = 0.
  ASSERT_EQ(r.motion_magnitudes.values.cols(), 1);
  const auto& mc = *r.motion_magnitudes.exact;
  const int ta = magnitude_index(r.motions, "ta"), tb = magnitude_index(r.motions, "tb");
  for (int i = 0; i < r.F; ++i)
    if (i != ta && i != tb) {
      EXPECT_EQ(mc(i, 0), 0) << r.motions[static_cast<std::size_t>(i)].name;
    }
  EXPECT_NE(mc(ta, 0), 0);
  EXPECT_EQ(mc(ta, 0), mc(tb, 0));
  // Section 2.2: all action magnitudes zero except Wa and Wb with Wa + Wb = 0 (same sense
  // across the cutset, as in the file).
  ASSERT_EQ(r.action_magnitudes.values.cols(), 1);
  const auto& ac = *r.action_magnitudes.exact;
  const int wa = magnitude_index(r.actions, "Wa"), wb = magnitude_index(r.actions, "Wb");
  for (int i = 0; i < r.C; ++i)
    if (i != wa && i != wb) {
      EXPECT_EQ(ac(i, 0), 0) << r.actions[static_cast<std::size_t>(i)].name;
    }
  EXPECT_NE(ac(wa, 0), 0);
  EXPECT_EQ(ac(wa, 0), -ac(wb, 0));
  // fij reduced from three to one; each coupling transmits one action (the z force).
  EXPECT_EQ(fij(model, r, "1", "2"), 1);
  EXPECT_EQ(cij(model, r, "A"), 1);
  EXPECT_EQ(cij(model, r, "B"), 1);
  // "The sixth row of [MD]6,6, being empty, is redundant"; "the third row of [AD]6,6 ...".
  EXPECT_EQ(r.circulation.solution.redundant_rows, (std::vector<Eigen::Index>{5}));
  EXPECT_EQ(r.cutset_law.solution.redundant_rows, (std::vector<Eigen::Index>{2}));
  // Sections 3.1 and 3.2: the virtual-power duals find the same one action and one motion.
  EXPECT_EQ(r.circuit_action.solution.nullity(), 1);
  EXPECT_EQ(r.cutset_motion.solution.nullity(), 1);
}

TEST(DaviesTwoCircuit, Table1) {
  const auto model = load_example("davies-2-circuit.yaml");
  const auto r = analyse(model);
  EXPECT_EQ(r.FN, 3);
  EXPECT_EQ(r.CN, 2);
  expect_consistent(r);
  // Seed 000, Table 1: fij and cij.
  EXPECT_EQ(fij(model, r, "1", "2"), 1);
  EXPECT_EQ(fij(model, r, "1", "3"), 2);
  EXPECT_EQ(fij(model, r, "1", "4"), 2);
  EXPECT_EQ(fij(model, r, "2", "3"), 1);
  EXPECT_EQ(fij(model, r, "2", "4"), 1);
  EXPECT_EQ(fij(model, r, "3", "4"), 2);
  EXPECT_EQ(cij(model, r, "D"), 1);
  EXPECT_EQ(cij(model, r, "E"), 2);
  EXPECT_EQ(cij(model, r, "C"), 2);
  EXPECT_EQ(cij(model, r, "B"), 1);
  EXPECT_EQ(cij(model, r, "A"), 2);
  // Section 2.5.1: "The discarded rows can be the second and the empty twelfth" of M^N
  // (12 x 13, rank 10), in either arithmetic; discarding them keeps the rank.
  const std::vector<Eigen::Index> discarded{1, 11};
  EXPECT_EQ(r.circulation.solution.redundant_rows, discarded);
  EXPECT_EQ(analyse(model, Arithmetic::floating).circulation.solution.redundant_rows, discarded);
  // A^N (18 x 17, rank 15) as printed in the seed: row 2 is empty, row 9 = -row 3 and
  // row 17 = -row 11, so the rows that depend on later rows are 2, 3 and 11. (The seed's
  // "the empty second, the third, and the ninth" cannot all be discarded: rows 3 and 9 are
  // the same equation, and dropping both leaves rank 14.)
  const std::vector<Eigen::Index> discarded_actions{1, 2, 10};
  EXPECT_EQ(r.cutset_law.solution.redundant_rows, discarded_actions);
  EXPECT_EQ(analyse(model, Arithmetic::floating).cutset_law.solution.redundant_rows, discarded_actions);
}

TEST(FourBar, PlanarIsAKinematicChain) {
  const auto model = load_example("four-bar-planar.yaml");
  const auto r = analyse(model);
  EXPECT_EQ(r.d, 3);
  EXPECT_EQ(r.F, 4);
  EXPECT_EQ(r.C, 8);
  EXPECT_EQ(r.l, 1);
  EXPECT_EQ(r.k, 3);
  EXPECT_EQ(r.FN, 1);  // planar Grübler-Kutzbach 3(4 - 1 - 4) + 4
  EXPECT_EQ(r.CN, 0);
  EXPECT_EQ(r.classification, NetworkClass::kinematic_chain);
  expect_consistent(r);
  // One-dof loop: every pair of bodies keeps one relative freedom, every joint one...
  EXPECT_EQ(fij(model, r, "ground", "crank"), 1);
  EXPECT_EQ(fij(model, r, "ground", "coupler"), 1);
  EXPECT_EQ(fij(model, r, "crank", "rocker"), 1);
  // ...and no joint carries a locked-in action.
  for (const char* joint : {"A", "B", "C", "D"}) EXPECT_EQ(cij(model, r, joint), 0) << joint;
}

TEST(FourBar, SpatialWithParallelAxesIsOverconstrained) {
  const auto model = load_example("four-bar-spatial.yaml");
  const auto r = analyse(model);
  EXPECT_EQ(r.d, 6);
  EXPECT_EQ(r.F, 4);
  EXPECT_EQ(r.C, 20);
  EXPECT_EQ(r.FN, 1);
  EXPECT_EQ(r.CN, 3);  // moments about x and y, force along z: FN - CN = 4 - 6
  EXPECT_EQ(r.classification, NetworkClass::overconstrained_chain);
  expect_consistent(r);
  EXPECT_EQ(fij(model, r, "ground", "coupler"), 1);
  // The locked-in 3-system (R, S moments and W force) reaches every joint.
  for (const char* joint : {"A", "B", "C", "D"}) EXPECT_EQ(cij(model, r, joint), 3) << joint;
}

TEST(SliderCrank, PlanarRRRP) {
  const auto model = load_example("slider-crank-planar.yaml");
  const auto r = analyse(model);
  EXPECT_EQ(r.F, 4);
  EXPECT_EQ(r.FN, 1);
  EXPECT_EQ(r.CN, 0);
  expect_consistent(r);
  EXPECT_EQ(fij(model, r, "ground", "slider"), 1);
}

TEST(Bennett, MobileAgainstGrueblerKutzbach) {
  const auto model = load_example("bennett.yaml");
  const auto r = analyse(model);
  EXPECT_TRUE(r.exact);  // integer geometry: no rounding anywhere
  EXPECT_EQ(r.F, 4);
  EXPECT_EQ(6 * (4 - 1 - 4) + r.F, -2);  // the Grübler-Kutzbach count the example refutes
  EXPECT_EQ(r.FN, 1);
  EXPECT_EQ(r.CN, 3);
  EXPECT_EQ(r.classification, NetworkClass::overconstrained_chain);
  expect_consistent(r);
  // Every joint turns: no motion magnitude is forced to zero.
  for (int i = 0; i < r.F; ++i) EXPECT_NE((*r.motion_magnitudes.exact)(i, 0), 0);
  EXPECT_EQ(fij(model, r, "ground", "link2"), 1);
  EXPECT_EQ(fij(model, r, "link1", "link3"), 1);
}

TEST(Bennett, PerturbedAxisMakesItRigid) {
  const auto model = load_example("bennett-perturbed.yaml");
  const auto r = analyse(model);
  EXPECT_TRUE(r.exact);
  EXPECT_EQ(r.FN, 0);
  EXPECT_EQ(r.CN, 2);
  EXPECT_EQ(r.classification, NetworkClass::overconstrained_structure);
  expect_consistent(r);
  EXPECT_EQ(fij(model, r, "ground", "link2"), 0);
}

TEST(Spherical4R, FourAxesThroughOnePoint) {
  const auto model = load_example("spherical-4r.yaml");
  const auto r = analyse(model);
  EXPECT_EQ(r.FN, 1);
  EXPECT_EQ(r.CN, 3);  // the three forces through the centre
  expect_consistent(r);
  EXPECT_EQ(fij(model, r, "ground", "coupler"), 1);
  for (const char* joint : {"A", "B", "C", "D"}) EXPECT_EQ(cij(model, r, joint), 3) << joint;
}

TEST(StewartGough, SixUPSIsAGenericSixDofChain) {
  const auto model = load_example("stewart-6ups.yaml");
  const auto r = analyse(model);
  EXPECT_EQ(r.bodies, 14);
  EXPECT_EQ(r.e, 18);
  EXPECT_EQ(r.F, 36);
  EXPECT_EQ(r.l, 5);
  EXPECT_EQ(r.k, 13);
  EXPECT_EQ(r.FN, 6);  // Merlet: mobility 6 = 6(14 - 1 - 18) + 36
  EXPECT_EQ(r.CN, 0);
  EXPECT_EQ(r.classification, NetworkClass::kinematic_chain);
  expect_consistent(r);
  EXPECT_EQ(fij(model, r, "base", "platform"), 6);
  // The lower link of a leg follows the U joint (two rotations); relative to the platform
  // it keeps the four freedoms of the P-S part of its leg (the leg's six joint screws are
  // independent, so the platform's six freedoms split uniquely into U, P and S parts).
  EXPECT_EQ(fij(model, r, "base", "leg1_lower"), 2);
  EXPECT_EQ(fij(model, r, "leg1_lower", "platform"), 4);
  EXPECT_EQ(fij(model, r, "base", "leg1_upper"), 3);
}

TEST(StewartGough, ActuatorsLockedMakeASimplyStiffStructure) {
  // Locking the six prismatic actuators (Merlet, ch. 4: the platform is then rigid, the six
  // leg lines being independent at a non-singular pose): FN = 0, CN = 0 (every leg line
  // transmits one force and the six forces are independent).
  auto model = load_example("stewart-6ups.yaml");
  for (auto& c : model.couplings)
    if (c.name[0] == 'P') c.type = screw::CouplingType::rigid;
  const auto r = analyse(model);
  EXPECT_EQ(r.F, 30);
  EXPECT_EQ(r.FN, 0);
  EXPECT_EQ(r.CN, 0);
  EXPECT_EQ(r.classification, NetworkClass::simply_stiff);
  expect_consistent(r);
}

TEST(Sarrus, StraightLineMotion) {
  const auto model = load_example("sarrus.yaml");
  const auto r = analyse(model);
  EXPECT_EQ(r.F, 6);
  EXPECT_EQ(6 * (6 - 1 - 6) + r.F, 0);  // Grübler-Kutzbach predicts a structure
  EXPECT_EQ(r.FN, 1);
  EXPECT_EQ(r.CN, 1);
  expect_consistent(r);
  EXPECT_EQ(fij(model, r, "base", "top"), 1);
  // The top plate's only motion relative to the base is the translation along z.
  const auto& pair = *std::find_if(r.pairs.begin(), r.pairs.end(), [&](const network::PairSystem& p) {
    return model.bodies[static_cast<std::size_t>(p.body_i)] == "base" && model.bodies[static_cast<std::size_t>(p.body_j)] == "top";
  });
  ASSERT_TRUE(pair.motion_system.exact.has_value());
  const auto& m = *pair.motion_system.exact;  // (r, s, t; u, v, w) of top relative to base
  for (int row = 0; row < 5; ++row) EXPECT_EQ(m(row, 0), 0) << row;
  EXPECT_NE(m(5, 0), 0);
}

TEST(Parallelogram, CouplerTranslates) {
  const auto model = load_example("parallelogram.yaml");
  const auto r = analyse(model);
  EXPECT_EQ(r.FN, 1);
  EXPECT_EQ(r.CN, 0);
  expect_consistent(r);
  const auto& pair = *std::find_if(r.pairs.begin(), r.pairs.end(), [&](const network::PairSystem& p) {
    const auto& a = model.bodies[static_cast<std::size_t>(p.body_i)];
    const auto& b = model.bodies[static_cast<std::size_t>(p.body_j)];
    return (a == "ground" && b == "coupler") || (a == "coupler" && b == "ground");
  });
  EXPECT_EQ(pair.fij, 1);
  // Planar motion (t; u, v): no rotation, translation along the crank's normal (-4, 2)...
  const auto& m = *pair.motion_system.exact;
  EXPECT_EQ(m(0, 0), 0);
  // ...i.e. perpendicular to the crank direction (2, 4): 2 u + 4 v = 0.
  EXPECT_EQ(2 * m(1, 0) + 4 * m(2, 0), 0);
  EXPECT_NE(m(1, 0), 0);
}

TEST(Parallelogram, RedundantCrankAddsOneSelfStress) {
  const auto model = load_example("parallelogram-redundant.yaml");
  const auto r = analyse(model);
  EXPECT_EQ(r.F, 6);
  EXPECT_EQ(r.l, 2);
  EXPECT_EQ(3 * (5 - 1 - 6) + r.F, 0);  // planar Grübler-Kutzbach predicts a structure
  EXPECT_EQ(r.FN, 1);
  EXPECT_EQ(r.CN, 1);
  expect_consistent(r);
  EXPECT_EQ(fij(model, r, "ground", "coupler"), 1);
  // The self-stress is a pair of opposite forces along the cranks: every joint carries it.
  for (const char* joint : {"A", "B", "C", "D", "E", "H"}) EXPECT_EQ(cij(model, r, joint), 1) << joint;
}

TEST(ScrewJack, NutAdvancesByPitchTimesAngle) {
  const auto model = load_example("screw-jack.yaml");
  const auto r = analyse(model);
  EXPECT_EQ(r.F, 3);
  EXPECT_EQ(r.FN, 1);
  EXPECT_EQ(r.CN, 4);
  expect_consistent(r);
  // v = h omega with h = 0.005 = 1/200: the prismatic magnitude is 1/200 of the revolute's.
  const auto& c = *r.motion_magnitudes.exact;
  int revolute = -1, prismatic = -1;
  for (std::size_t i = 0; i < r.motions.size(); ++i) {
    const auto& name = model.couplings[static_cast<std::size_t>(r.motions[i].coupling)].name;
    if (name == "R") revolute = static_cast<int>(i);
    if (name == "P") prismatic = static_cast<int>(i);
  }
  ASSERT_GE(revolute, 0);
  ASSERT_GE(prismatic, 0);
  EXPECT_NE(c(revolute, 0), 0);
  EXPECT_EQ(abs(c(prismatic, 0)), abs(c(revolute, 0)) / 200);
  // With lengths in units 1000 times smaller the pitch is 5 units per radian.
  const auto small_units = analyse(scaled(model, 1000));
  const auto& k = *small_units.motion_magnitudes.exact;
  EXPECT_EQ(abs(k(prismatic, 0)), 5 * abs(k(revolute, 0)));
  EXPECT_EQ(fij(model, r, "ground", "nut"), 1);
}

TEST(Tsai3UPU, PlatformOnlyTranslates) {
  const auto model = load_example("tsai-3upu.yaml");
  const auto r = analyse(model);
  EXPECT_EQ(r.F, 15);
  EXPECT_EQ(r.l, 2);
  EXPECT_EQ(r.FN, 3);  // Tsai 1996: three translations
  EXPECT_EQ(r.CN, 0);
  EXPECT_EQ(r.classification, NetworkClass::kinematic_chain);
  expect_consistent(r);
  const auto& pair = *std::find_if(r.pairs.begin(), r.pairs.end(), [&](const network::PairSystem& p) {
    const auto& a = model.bodies[static_cast<std::size_t>(p.body_i)];
    const auto& b = model.bodies[static_cast<std::size_t>(p.body_j)];
    return (a == "base" && b == "platform") || (a == "platform" && b == "base");
  });
  EXPECT_EQ(pair.fij, 3);
  // No rotation of the platform relative to the base, for any value of the primaries: the
  // rows r, s, t of its motion system vanish; u, v, w span all three translations.
  ASSERT_TRUE(pair.motion_system.exact.has_value());
  const auto& m = *pair.motion_system.exact;
  for (int row = 0; row < 3; ++row)
    for (Eigen::Index p = 0; p < m.cols(); ++p) EXPECT_EQ(m(row, p), 0) << row;
  EXPECT_EQ(linalg::exact_rank(m.block(3, 0, 3, m.cols())), 3);
  // CN = 0: the three leg torques are independent, so none can be locked in (cij = 0).
  EXPECT_EQ(cij(model, r, "P1"), 0);
  EXPECT_EQ(cij(model, r, "U2a"), 0);
}

}  // namespace
}  // namespace kinestat::mechanisms_test
