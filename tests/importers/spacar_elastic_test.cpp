// SPDX-License-Identifier: BSD-3-Clause
// SPACAR's stiffness and mass cards (issue 38 item 1; docs/formats.md: ESTIFF, EM, XM as SPACAR
// Light 1.38 writes them): read into sections given by their rigidities and node masses,
// written back by convert, and the stiffness of an imported leaf-spring guide by hand.

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "kinestat/framework/stiffness.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/framework_yaml_writer.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/spacar_reader.hpp"
#include "kinestat/io/spacar_writer.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace kinestat::io {
namespace {

// Spring steel leaves (mm, N): l = 40, width 10 along y, thickness 0.2 along x, 50 apart.
constexpr double kE = 210000, kG = 80000, kLength = 40, kWidth = 10, kThickness = 0.2, kApart = 50;
const double kArea = kWidth * kThickness;
const double kIy = kWidth * kThickness * kThickness * kThickness / 12;  // bending across the thin side
const double kIz = kThickness * kWidth * kWidth * kWidth / 12;
const double kIt = kWidth * kThickness * kThickness * kThickness / 3;  // thin sheet (any value does here)

// The parallel leaf-spring guide of examples/spacar in SPACAR Light's layout, with the cards
// spacarlight.m writes after END HALT: ESTIFF (with shear terms), EM and XM.
std::string guide_dat() {
  return fmt::format(
      "X 1 -25 0 0\nX 3 25 0 0\nX 5 -25 0 40\nX 7 25 0 40\n"
      "BEAM 1 1 2 5 6 0 1 0\nBEAM 2 3 4 7 8 0 1 0\nBEAM 3 5 6 7 8 0 1 0\n"
      "DYNE 1 1 5 6\nRLSE 1 2 3 4\nDYNE 2 1 5 6\nRLSE 2 2 3 4\nFIX 1\nFIX 2\nFIX 3\nFIX 4\nEND\nHALT\n"
      "#STIFFNESS Ne EA GJ EIy EIz Shear Y Shear Z\n"
      "ESTIFF 1 {0} {1} {2} {3} 0.001 0.002\nESTIFF 2 {0} {1} {2} {3} 0.001 0.002\n"
      "EM 1 1.57e-8 0 0 0 0\nEM 2 1.57e-8 0 0 0 0\n"
      "XM 5 1e-4\nXM 6 0.5 0 0 0.25 0 0.75\nITERSTEP 10 1 0.0000005 1 1 0\nEND\nEND\n",
      kE * kArea, kG * kIt, kE * kIy, kE * kIz);
}

std::size_t node_named(const framework::FrameworkModel& model, const std::string& name) {
  for (std::size_t n = 0; n < model.nodes.size(); ++n)
    if (model.nodes[n].name == name) return n;
  ADD_FAILURE() << "no node " << name;
  return 0;
}

TEST(SpacarElastic, CardsBecomeRigiditySectionsAndNodeMasses) {
  const SpacarImport imported = parse_spacar("guide.dat", guide_dat());
  const framework::FrameworkModel& model = imported.model;
  ASSERT_EQ(model.sections.size(), 2u);
  const framework::Section& leaf = model.sections[0];
  EXPECT_EQ(leaf.shape, framework::SectionShape::rigidities);
  EXPECT_DOUBLE_EQ(leaf.area, kE * kArea);  // E A
  EXPECT_DOUBLE_EQ(leaf.torsion, kG * kIt);
  EXPECT_DOUBLE_EQ(leaf.iy, kE * kIy);
  EXPECT_DOUBLE_EQ(leaf.iz, kE * kIz);
  EXPECT_DOUBLE_EQ(leaf.mass_per_length, 1.57e-8);
  // The connector (element 3) has no ESTIFF: rigid, no section.
  EXPECT_FALSE(model.elements[2].section.has_value());
  ASSERT_EQ(model.masses.size(), 1u);  // XM 5 (position) and XM 6 (its orientation): one node
  EXPECT_EQ(model.nodes[model.masses[0].node].name, "5");
  EXPECT_DOUBLE_EQ(model.masses[0].mass, 1e-4);
  ASSERT_TRUE(model.masses[0].inertia.has_value());
  EXPECT_EQ(*model.masses[0].inertia, Eigen::Vector3d(0.5, 0.25, 0.75));
  // The shear terms have no counterpart: one note each; ITERSTEP is still skipped.
  int shear_notes = 0;
  for (const std::string& notice : imported.notices) shear_notes += notice.find("shear-flexibility") != std::string::npos;
  EXPECT_EQ(shear_notes, 2);
  EXPECT_NE(imported.notices.back().find("ITERSTEP"), std::string::npos) << imported.notices.back();
}

TEST(SpacarElastic, ImportedGuideHasTheClampedGuidedStiffnessByHand) {
  // By hand at node 5 (top of leaf 1; the connector rigid): along x both leaves bend
  // clamped-guided, 2 · 12 E Iy / l³ = 24 E Iy / l³; the connector turning about y by θ turns
  // both tips (4 E Iy / l each) and, with node 5's z free too, lifts one leaf tip by d θ / 2 and
  // lowers the other (E A / l each: E A d² / (2 l)), coupled to x by 2 · (−6 E Iy / l²). Pushing
  // x with every other coordinate free: 24EIy/l³ − (12EIy/l²)² / (8EIy/l + EA d²/(2l)).
  const framework::FrameworkModel model = parse_spacar("guide.dat", guide_dat()).model;
  const framework::NodeStiffness k = framework::stiffness_at(model, node_named(model, "5"));
  const double ei = kE * kIy, l = kLength;
  const double along = 24 * ei / (l * l * l) - std::pow(12 * ei / (l * l), 2) / (8 * ei / l + kE * kArea * kApart * kApart / (2 * l));
  ASSERT_FALSE(k.motion.empty() && k.support.empty());
  double x = 0;
  for (const auto& d : k.support)
    if (d.coordinate == "x") x = d.stiffness;
  for (const auto& d : k.motion)
    if (d.coordinate == "x") x = d.stiffness;
  EXPECT_NEAR(x, along, 1e-9 * along);
  EXPECT_NEAR(along, 24 * ei / (l * l * l), 1e-4 * along);  // 24EI/L³ up to the platform's turn
}

TEST(SpacarElastic, ConvertWritesTheCardsAndReadsThemBack) {
  // YAML with material and rectangle -> .dat -> model: the rigidities are E A, G J, E Iy, E Iz
  // of the section, the mass per length ρ A, the node mass kept; the stiffness at the guide's
  // platform node is the same either way.
  const framework::FrameworkModel yaml = read_framework_model(YamlFile::load(std::string(KINESTAT_SOURCE_DIR) +
                                                                             "/examples/parallel-leaf-spring-guide-steel.yaml"));
  const std::string dat = spacar_text(yaml, {});
  EXPECT_NE(dat.find("ESTIFF"), std::string::npos);
  const framework::FrameworkModel back = parse_spacar("steel.dat", dat).model;
  ASSERT_EQ(back.sections.size(), 2u);
  const framework::Section& leaf = back.sections[0];
  const double w = 10, t = 0.2, e = 210000, g = e / (2 * 1.3);
  EXPECT_NEAR(leaf.area, e * w * t, 1e-9 * e);
  EXPECT_NEAR(leaf.iy, e * w * t * t * t / 12, 1e-9 * e);
  EXPECT_NEAR(leaf.iz, e * t * w * w * w / 12, 1e-9 * e);
  EXPECT_NEAR(leaf.torsion, g * framework::rectangle_torsion_constant(w, t), 1e-9 * g);
  EXPECT_NEAR(leaf.mass_per_length, 7.85e-9 * w * t, 1e-20);
  ASSERT_EQ(back.masses.size(), 1u);
  EXPECT_DOUBLE_EQ(back.masses[0].mass, 1e-4);
  // P (the fifth node) is SPACAR position node 9.
  const framework::NodeStiffness before = framework::stiffness_at(yaml, node_named(yaml, "P"));
  const framework::NodeStiffness after = framework::stiffness_at(back, node_named(back, "9"));
  ASSERT_EQ(before.matrix.rows(), after.matrix.rows());
  EXPECT_LE((before.matrix - after.matrix).norm(), 1e-9 * before.matrix.norm());
  // And the YAML of the imported model keeps the rigidities.
  const framework::FrameworkModel again = read_framework_model(YamlFile::parse("again.yaml", framework_yaml(back)));
  ASSERT_EQ(again.sections.size(), 2u);
  EXPECT_EQ(again.sections[0].shape, framework::SectionShape::rigidities);
  EXPECT_DOUBLE_EQ(again.sections[0].iy, leaf.iy);
  EXPECT_DOUBLE_EQ(again.sections[0].mass_per_length, leaf.mass_per_length);
}

TEST(SpacarElastic, BadCardsAreLocated) {
  std::string text = guide_dat();
  text.replace(text.find("ESTIFF 2"), 8, "ESTIFF 9");
  try {
    parse_spacar("guide.dat", text);
    FAIL() << "ESTIFF of an unknown element was read";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("no element 9"), std::string::npos) << error.what();
  }
  text = guide_dat();
  text.replace(text.find("XM 5 1e-4"), 9, "XM 5 1e-4 2");
  EXPECT_THROW(parse_spacar("guide.dat", text), InputError);
}

}  // namespace
}  // namespace kinestat::io
