// SPDX-License-Identifier: BSD-3-Clause
// Position analysis group by group (issue 13, item 3): positions checked against closed forms
// written here (law of cosines, Freudenstein's equation, circle-line and line-line
// intersections) and against positions computed by an independent script
// (data/independent_positions.py, whole-mechanism Newton on link distances).

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/network_structure.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/kinematics/position_solver.hpp"
#include "kinestat/structure/decomposition.hpp"

namespace {

using kinestat::kinematics::AssemblyStatus;
using kinestat::kinematics::GroupMethod;
using kinestat::kinematics::PositionResult;
using Point = std::pair<double, double>;
using ExpectedTable = std::vector<std::pair<double, std::map<std::string, Point>>>;

constexpr double kPi = std::numbers::pi;

std::string data(const std::string& name) { return std::string(KINESTAT_SOURCE_DIR) + "/tests/kinematics/data/" + name; }
std::string example(const std::string& name) { return std::string(KINESTAT_SOURCE_DIR) + "/examples/" + name; }

struct Mechanism {
  kinestat::network::Model model;
  kinestat::kinematics::PositionPlan plan;
};

Mechanism prepare(const std::string& path, const std::vector<std::string>& inputs) {
  auto loaded = kinestat::io::read_network_model(kinestat::io::YamlFile::load(path));
  loaded.model.inputs = inputs;
  const auto structure = kinestat::io::structure_of_network(loaded, path);
  const auto decomposition = kinestat::structure::analyse_structure(structure);
  return {loaded.model, kinestat::kinematics::plan_positions(loaded.model, structure, decomposition)};
}

// Solves at each value in turn, continuing from the last assembled configuration.
std::vector<PositionResult> sweep(const Mechanism& m, const std::vector<double>& values) {
  std::vector<PositionResult> results;
  std::vector<kinestat::kinematics::Pose> start;
  for (double v : values) {
    results.push_back(kinestat::kinematics::solve_positions(m.model, m.plan, {v}, start));
    if (results.back().assembled) start = results.back().poses;
  }
  return results;
}

std::vector<double> full_turn(int steps) {
  std::vector<double> values;
  for (int k = 0; k <= steps; ++k) values.push_back(2 * kPi * k / steps);
  return values;
}

Point joint(const Mechanism& m, const PositionResult& r, const std::string& name) {
  for (std::size_t c = 0; c < m.model.couplings.size(); ++c) {
    if (m.model.couplings[c].name == name) {
      const auto p = kinestat::kinematics::coupling_point(m.model, r.poses, static_cast<int>(c));
      return {p[0], p[1]};
    }
  }
  ADD_FAILURE() << "no coupling " << name;
  return {0, 0};
}

int body(const Mechanism& m, const std::string& name) {
  for (std::size_t b = 0; b < m.model.bodies.size(); ++b)
    if (m.model.bodies[b] == name) return static_cast<int>(b);
  ADD_FAILURE() << "no body " << name;
  return 0;
}

void expect_point(const Point& got, double x, double y, double tolerance, const std::string& what) {
  EXPECT_NEAR(got.first, x, tolerance) << what;
  EXPECT_NEAR(got.second, y, tolerance) << what;
}

// Intersection of the circles about P (radius r) and Q (radius s) on the side where
// cross(Q − P, X − P) has sign `side`: law of cosines for the angle at P.
Point circle_circle(Point P, double r, Point Q, double s, int side) {
  const double dx = Q.first - P.first, dy = Q.second - P.second, d = std::hypot(dx, dy);
  const double cos_angle = (d * d + r * r - s * s) / (2 * d * r);
  const double angle = side * std::acos(cos_angle);
  const double ux = dx / d, uy = dy / d;
  return {P.first + r * (std::cos(angle) * ux - std::sin(angle) * uy), P.second + r * (std::sin(angle) * ux + std::cos(angle) * uy)};
}

// watt-six-bar-planar.yaml: independent_positions.py (whole-mechanism Newton on link distances).
const ExpectedTable kWatt = {
    {0.0, {{"A", {0, 0}}, {"B", {6.12323399573677e-17, 1}}, {"C", {4, 3}}, {"D", {4, 0}}, {"E", {6, 2}}, {"F", {8, 4}}, {"G", {9, 0}}}},
    {0.5, {{"A", {0, 0}}, {"B", {-0.479425538604203, 0.877582561890373}}, {"C", {3.48103938552341, 2.95477239066262}}, {"D", {4, 0}}, {"E", {5.62387451745735, 2.31582200342614}}, {"F", {7.91292667210698, 3.97721907616158}}, {"G", {9, 0}}}},
    {1.0, {{"A", {0, 0}}, {"B", {-0.841470984807897, 0.54030230586814}}, {"C", {3.00081555020497, 2.82871533302448}}, {"D", {4, 0}}, {"E", {5.2196872554863, 2.55193318854634}}, {"F", {7.69933353101189, 3.91257801665986}}, {"G", {9, 0}}}},
    {2.0, {{"A", {0, 0}}, {"B", {-0.909297426825682, -0.416146836547142}}, {"C", {2.43127326471609, 2.5571657024928}}, {"D", {4, 0}}, {"E", {4.65895931147259, 2.75059495851781}}, {"F", {7.30216410284085, 3.75730665055673}}, {"G", {9, 0}}}},
    {3.0, {{"A", {0, 0}}, {"B", {-0.141120008059867, -0.989992496600445}}, {"C", {2.51595445933645, 2.60722243647078}}, {"D", {4, 0}}, {"E", {4.74878459720482, 2.72751198475622}}, {"F", {7.37101220909238, 3.78766402642498}}, {"G", {9, 0}}}},
    {4.0, {{"A", {0, 0}}, {"B", {0.756802495307928, -0.653643620863612}}, {"C", {3.41535373081807, 2.94248003220611}}, {"D", {4, 0}}, {"E", {5.57188917534945, 2.35141753425869}}, {"F", {7.89066737545682, 3.97106800849899}}, {"G", {9, 0}}}},
    {5.0, {{"A", {0, 0}}, {"B", {0.958924274663138, 0.283662185463226}}, {"C", {4.54989284666659, 2.94917240207908}}, {"D", {4, 0}}, {"E", {6.33271016583045, 1.59951970360833}}, {"F", {7.87906379147114, 3.96780821315861}}, {"G", {9, 0}}}},
    {6.0, {{"A", {0, 0}}, {"B", {0.279415498198926, 0.960170286650366}}, {"C", {4.26525171202628, 2.98825058006639}}, {"D", {4, 0}}, {"E", {6.16900152806178, 1.81533257869341}}, {"F", {7.97356839603912, 3.99329915763774}}, {"G", {9, 0}}}},
};

// stephenson-six-bar-planar.yaml: independent_positions.py (whole-mechanism Newton on link distances).
const ExpectedTable kStephenson = {
    {0.0, {{"A", {0, 0}}, {"B", {6.12323399573677e-17, 1}}, {"C", {4, 3}}, {"D", {4, 0}}, {"E", {2, 4}}, {"F", {-1, 5}}, {"G", {-2, 2}}}},
    {0.5, {{"A", {0, 0}}, {"B", {-0.479425538604203, 0.877582561890373}}, {"C", {3.48103938552341, 2.95477239066262}}, {"D", {4, 0}}, {"E", {1.46202397677623, 3.91580141168199}}, {"F", {-1.46346619011467, 5.11642928218337}}, {"G", {-2, 2}}}},
    {1.0, {{"A", {0, 0}}, {"B", {-0.841470984807897, 0.54030230586814}}, {"C", {3.00081555020497, 2.82871533302448}}, {"D", {4, 0}}, {"E", {0.932764378838572, 3.67910603888272}}, {"F", {-1.86172392416959, 5.15925303305274}}, {"G", {-2, 2}}}},
    {2.0, {{"A", {0, 0}}, {"B", {-0.909297426825682, -0.416146836547142}}, {"C", {2.43127326471609, 2.5571657024928}}, {"D", {4, 0}}, {"E", {0.239777041637582, 3.00140021739752}}, {"F", {-2.06975392911639, 5.16150824597578}}, {"G", {-2, 2}}}},
    {3.0, {{"A", {0, 0}}, {"B", {-0.141120008059867, -0.989992496600445}}, {"C", {2.51595445933645, 2.60722243647078}}, {"D", {4, 0}}, {"E", {0.279946145889062, 2.59088774350794}}, {"F", {-1.59631143984493, 5.13640487603242}}, {"G", {-2, 2}}}},
    {4.0, {{"A", {0, 0}}, {"B", {0.756802495307928, -0.653643620863612}}, {"C", {3.41535373081807, 2.94248003220611}}, {"D", {4, 0}}, {"E", {1.17933889893714, 2.92706343048925}}, {"F", {-1.16449136763485, 5.04990578956848}}, {"G", {-2, 2}}}},
    {5.0, {{"A", {0, 0}}, {"B", {0.958924274663138, 0.283662185463226}}, {"C", {4.54989284666659, 2.94917240207908}}, {"D", {4, 0}}, {"E", {2.40639818841921, 3.58590676589571}}, {"F", {-0.516541068882114, 4.79273156599172}}, {"G", {-2, 2}}}},
    {6.0, {{"A", {0, 0}}, {"B", {0.279415498198926, 0.960170286650366}}, {"C", {4.26525171202628, 2.98825058006639}}, {"D", {4, 0}}, {"E", {2.25826873051166, 3.97416097757252}}, {"F", {-0.762354156707343, 4.9100228120378}}, {"G", {-2, 2}}}},
};

// class-iii-triad-planar.yaml: independent_positions.py (whole-mechanism Newton on link distances).
const ExpectedTable kTriad = {
    {0.0, {{"A", {0, 0}}, {"B", {6.12323399573677e-17, 1}}, {"C", {3, 2}}, {"D", {4, 4}}, {"E", {2, 9}}, {"F", {6, -1}}, {"G", {3, -4}}}},
    {0.5, {{"A", {0, 0}}, {"B", {-0.479425538604203, 0.877582561890373}}, {"C", {2.5815007856533, 1.67176770243849}}, {"D", {3.32536733941243, 3.7804788135674}}, {"E", {2, 9}}, {"F", {5.93086085342987, -0.932418761005285}}, {"G", {3, -4}}}},
    {1.0, {{"A", {0, 0}}, {"B", {-0.841470984807897, 0.54030230586814}}, {"C", {2.17440580347764, 1.49134762438904}}, {"D", {2.71126062068293, 3.66201270800822}}, {"E", {2, 9}}, {"F", {5.75949006366899, -0.777390096751998}}, {"G", {3, -4}}}},
    {2.0, {{"A", {0, 0}}, {"B", {-0.909297426825682, -0.416146836547142}}, {"C", {1.67592650179269, 1.40501137703536}}, {"D", {2.01732872622885, 3.61486307367702}}, {"E", {2, 9}}, {"F", {5.44881822108598, -0.535423644934739}}, {"G", {3, -4}}}},
    {3.0, {{"A", {0, 0}}, {"B", {-0.141120008059867, -0.989992496600445}}, {"C", {1.89694427192924, 1.42791858336765}}, {"D", {2.31701610973218, 3.62417440887725}}, {"E", {2, 9}}, {"F", {5.59816165516476, -0.645964219983407}}, {"G", {3, -4}}}},
    {4.0, {{"A", {0, 0}}, {"B", {0.756802495307928, -0.653643620863612}}, {"C", {2.76126341466609, 1.7921970163746}}, {"D", {3.60970880990134, 3.86104703783679}}, {"E", {2, 9}}, {"F", {5.97612621615689, -0.976314707926157}}, {"G", {3, -4}}}},
    {5.0, {{"A", {0, 0}}, {"B", {0.958924274663138, 0.283662185463226}}, {"C", {3.31931461462847, 2.38807598578823}}, {"D", {4.54845751476224, 4.25601809705688}}, {"E", {2, 9}}, {"F", {5.94412467483177, -0.945146501213731}}, {"G", {3, -4}}}},
    {6.0, {{"A", {0, 0}}, {"B", {0.279415498198926, 0.960170286650366}}, {"C", {3.18543687535082, 2.20718261840021}}, {"D", {4.31419895633529, 4.13744067486096}}, {"E", {2, 9}}, {"F", {5.98264412838948, -0.982743961248276}}, {"G", {3, -4}}}},
};

void expect_table(const std::string& file, const ExpectedTable& expected) {
  const Mechanism m = prepare(data(file), {"A"});
  // 0 to 6 rad in steps of 0.05 hits every tabulated input.
  std::vector<double> values;
  for (int k = 0; k <= 120; ++k) values.push_back(0.05 * k);
  const auto results = sweep(m, values);
  for (const auto& r : results) {
    ASSERT_TRUE(r.assembled) << file;
    EXPECT_LT(r.max_residual, 1e-10) << file;
  }
  for (const auto& [value, joints] : expected) {
    const auto& r = results[static_cast<std::size_t>(std::lround(value / 0.05))];
    for (const auto& [name, p] : joints) expect_point(joint(m, r, name), p.first, p.second, 1e-9, file + " " + name + " at " + std::to_string(value));
  }
}

TEST(PositionSolver, FourBarCrankRockerOverAFullTurnMatchesTheLawOfCosinesAndFreudenstein) {
  const Mechanism m = prepare(data("four-bar-crank-rocker.yaml"), {"A"});
  ASSERT_EQ(m.plan.groups.size(), 2u);
  EXPECT_EQ(m.plan.groups[0].method, GroupMethod::driving_link);
  EXPECT_EQ(m.plan.groups[1].type, "dyad RRR");
  EXPECT_EQ(m.plan.groups[1].method, GroupMethod::closed_form);
  // a = AB, b = BC, c = CD, d = AD; the file has C left of B→D: cross(D − B, C − B) = 12 > 0.
  const double a = 1, b = std::sqrt(20.0), c = 3, d = 4;
  const auto values = full_turn(72);
  const auto results = sweep(m, values);
  for (std::size_t k = 0; k < values.size(); ++k) {
    const auto& r = results[k];
    ASSERT_TRUE(r.assembled) << values[k];
    EXPECT_LT(r.max_residual, 1e-10);
    const double theta = kPi / 2 + values[k];  // crank angle from the frame line A→D
    const Point B{a * std::cos(theta), a * std::sin(theta)};
    const Point C = circle_circle(B, b, {d, 0}, c, +1);
    expect_point(joint(m, r, "B"), B.first, B.second, 1e-12, "B");
    expect_point(joint(m, r, "C"), C.first, C.second, 1e-10, "C");
    // Freudenstein: (d/a) cos φ − (d/c) cos θ + (a² − b² + c² + d²)/(2ac) = cos(θ − φ), φ the rocker's angle.
    const Point got = joint(m, r, "C");
    const double phi = std::atan2(got.second, got.first - d);
    EXPECT_NEAR(d / a * std::cos(phi) - d / c * std::cos(theta) + (a * a - b * b + c * c + d * d) / (2 * a * c), std::cos(theta - phi),
                1e-10);
  }
}

TEST(PositionSolver, NonGrashofFourBarCannotBeAssembledBeyondTheLimitAngle) {
  // examples/four-bar-planar.yaml: AB = √5, BC = CD = √10, AD = 5; s + l = √5 + 5 > p + q = 2√10,
  // so no link turns fully. The crank (absolute angle θ) reaches while BD ≤ BC + CD:
  // BD² = 5 + 25 − 10√5 cos θ ≤ 40, cos θ ≥ −1/√5. In the file θ0 = atan2(2, 1), so the input
  // (θ − θ0) is limited to [−π, arccos(−1/√5) − atan2(2, 1)] = [−π, atan(4/3)].
  const double limit = std::acos(-1 / std::sqrt(5.0)) - std::atan2(2.0, 1.0);
  EXPECT_NEAR(limit, std::atan(4.0 / 3), 1e-12);
  const Mechanism m = prepare(example("four-bar-planar.yaml"), {"A"});
  const auto inside = kinestat::kinematics::solve_positions(m.model, m.plan, {limit - 1e-6});
  EXPECT_TRUE(inside.assembled);
  const auto outside = kinestat::kinematics::solve_positions(m.model, m.plan, {limit + 1e-6});
  EXPECT_FALSE(outside.assembled);
  ASSERT_TRUE(outside.failed_group.has_value());
  EXPECT_EQ(m.plan.groups[*outside.failed_group].number, 2);
  EXPECT_EQ(outside.groups[*outside.failed_group].status, AssemblyStatus::not_assembled);
  const auto values = full_turn(360);
  const auto results = sweep(m, values);
  for (std::size_t k = 0; k < values.size(); ++k) {
    const double v = values[k];
    if (std::abs(v - limit) < 1e-6 || std::abs(v - kPi) < 1e-6) continue;  // the limit positions themselves
    EXPECT_EQ(results[k].assembled, !(v > limit && v < kPi)) << v;
  }
}

TEST(PositionSolver, SliderCrankOverAFullTurnMatchesTheCircleLineIntersection) {
  // examples/slider-crank-planar.yaml: crank AB = √5, rod BC = √20, slider on y = 0, C right of B.
  const Mechanism m = prepare(example("slider-crank-planar.yaml"), {"A"});
  ASSERT_EQ(m.plan.groups.size(), 2u);
  EXPECT_EQ(m.plan.groups[1].type, "dyad RRP");
  const auto values = full_turn(72);
  const auto results = sweep(m, values);
  for (std::size_t k = 0; k < values.size(); ++k) {
    ASSERT_TRUE(results[k].assembled);
    EXPECT_LT(results[k].max_residual, 1e-10);
    const double theta = std::atan2(2.0, 1.0) + values[k];
    const double bx = std::sqrt(5.0) * std::cos(theta), by = std::sqrt(5.0) * std::sin(theta);
    expect_point(joint(m, results[k], "C"), bx + std::sqrt(20 - by * by), 0.0, 1e-10, "C");
  }
}

TEST(PositionSolver, SliderCrankDrivenAtTheSliderPlacesTheCrankByTheLawOfCosines) {
  // Input on the prismatic P (between [slider, ground]): the value is the slide of the ground
  // relative to the slider, so the slider pin C is at (5 − v, 0). Then {crank, rod} is an RRR
  // dyad: B on the circles about A (√5) and C (√20), above the x-axis as in the file.
  const Mechanism m = prepare(example("slider-crank-planar.yaml"), {"P"});
  ASSERT_EQ(m.plan.groups.size(), 2u);
  EXPECT_EQ(m.plan.groups[0].type, "driving link P");
  EXPECT_EQ(m.plan.groups[1].type, "dyad RRR");
  for (double v : {-1.5, -0.5, 0.0, 0.5, 1.0, 1.5}) {
    const auto r = kinestat::kinematics::solve_positions(m.model, m.plan, {v});
    ASSERT_TRUE(r.assembled) << v;
    EXPECT_LT(r.max_residual, 1e-10);
    expect_point(joint(m, r, "C"), 5 - v, 0.0, 1e-12, "C");
    // cross(C − A, B − A) > 0 in the file (B above the line A→C).
    const Point B = circle_circle({0, 0}, std::sqrt(5.0), {5 - v, 0}, std::sqrt(20.0), +1);
    expect_point(joint(m, r, "B"), B.first, B.second, 1e-10, "B");
  }
  // |AC| > √5 + √20 = 6.708: the rod cannot reach.
  const auto far = kinestat::kinematics::solve_positions(m.model, m.plan, {-1.8});
  EXPECT_FALSE(far.assembled);
}

TEST(PositionSolver, InvertedSliderCrankRockerPointsAtTheCrankPin) {
  // RPR dyad: the rocker's slide axis passes through D and the crank pin B at every input.
  const Mechanism m = prepare(data("inverted-slider-crank.yaml"), {"A"});
  EXPECT_EQ(m.plan.groups[1].type, "dyad RPR");
  EXPECT_EQ(m.plan.groups[1].method, GroupMethod::closed_form);
  const auto values = full_turn(72);
  const auto results = sweep(m, values);
  const double start = std::atan2(2.0, -4.0);  // direction D→B in the file
  for (std::size_t k = 0; k < values.size(); ++k) {
    ASSERT_TRUE(results[k].assembled);
    const double theta = std::atan2(2.0, 1.0) + values[k];
    const double bx = std::sqrt(5.0) * std::cos(theta), by = std::sqrt(5.0) * std::sin(theta);
    const double expected = std::remainder(std::atan2(by, bx - 5) - start, 2 * kPi);
    const double got = results[k].poses[static_cast<std::size_t>(body(m, "rocker"))].angle;
    EXPECT_NEAR(std::remainder(got - expected, 2 * kPi), 0.0, 1e-10) << values[k];
    expect_point(joint(m, results[k], "B"), bx, by, 1e-10, "B");
  }
}

TEST(PositionSolver, SlottedCrankMeetsTheHorizontalLineAndFailsWhenParallel) {
  // PRP dyad: B on the crank's line (angle θ through A) and on y = 2: x_B = 2 cot θ.
  const Mechanism m = prepare(data("slotted-crank.yaml"), {"A"});
  EXPECT_EQ(m.plan.groups[1].type, "dyad PRP");
  const double theta0 = std::atan2(2.0, 1.0);
  for (double v : {-0.9, -0.5, 0.0, 0.3, 1.0, 1.9}) {
    const auto r = kinestat::kinematics::solve_positions(m.model, m.plan, {v});
    ASSERT_TRUE(r.assembled) << v;
    expect_point(joint(m, r, "B"), 2 / std::tan(theta0 + v), 2.0, 1e-10, "B");
  }
  // The crank horizontal (θ = π): its slot is parallel to y = 2 and misses it.
  const auto r = kinestat::kinematics::solve_positions(m.model, m.plan, {kPi - theta0});
  EXPECT_FALSE(r.assembled);
  ASSERT_TRUE(r.failed_group.has_value());
  EXPECT_EQ(r.groups[*r.failed_group].status, AssemblyStatus::not_assembled);
}

TEST(PositionSolver, WattSixBarMatchesTheIndependentSolution) {
  const Mechanism m = prepare(data("watt-six-bar-planar.yaml"), {"A"});
  ASSERT_EQ(m.plan.groups.size(), 3u);
  EXPECT_EQ(m.plan.groups[1].type, "dyad RRR");
  EXPECT_EQ(m.plan.groups[2].type, "dyad RRR");
  expect_table("watt-six-bar-planar.yaml", kWatt);
}

TEST(PositionSolver, StephensonSixBarMatchesTheIndependentSolution) {
  const Mechanism m = prepare(data("stephenson-six-bar-planar.yaml"), {"A"});
  ASSERT_EQ(m.plan.groups.size(), 3u);
  EXPECT_EQ(m.plan.groups[2].method, GroupMethod::closed_form);
  expect_table("stephenson-six-bar-planar.yaml", kStephenson);
}

TEST(PositionSolver, TriadIsSolvedByNewtonAndMatchesTheIndependentSolution) {
  const Mechanism m = prepare(data("class-iii-triad-planar.yaml"), {"A"});
  ASSERT_EQ(m.plan.groups.size(), 2u);
  EXPECT_EQ(m.plan.groups[1].bodies.size(), 4u);
  EXPECT_EQ(m.plan.groups[1].method, GroupMethod::newton);
  EXPECT_NE(m.plan.groups[1].type.find("triad"), std::string::npos);
  expect_table("class-iii-triad-planar.yaml", kTriad);
}

TEST(PositionSolver, TheFilesConfigurationIsReachedAtZeroInput) {
  for (const char* file : {"watt-six-bar-planar.yaml", "stephenson-six-bar-planar.yaml", "class-iii-triad-planar.yaml"}) {
    const Mechanism m = prepare(data(file), {"A"});
    const auto r = kinestat::kinematics::solve_positions(m.model, m.plan, {0.0});
    ASSERT_TRUE(r.assembled) << file;
    for (const auto& pose : r.poses) {
      EXPECT_NEAR(pose.x, 0.0, 1e-12) << file;
      EXPECT_NEAR(pose.y, 0.0, 1e-12) << file;
      EXPECT_NEAR(pose.angle, 0.0, 1e-12) << file;
    }
  }
}

TEST(PositionSolver, RefusesWhatItCannotSolve) {
  // Two inputs on a mobility-1 four-bar: the inputs do not decompose it.
  EXPECT_THROW(prepare(example("four-bar-planar.yaml"), {"A", "D"}), kinestat::kinematics::PositionModelError);
  // A spatial model.
  EXPECT_THROW(prepare(example("four-bar-spatial.yaml"), {}), kinestat::kinematics::PositionModelError);
}

}  // namespace
