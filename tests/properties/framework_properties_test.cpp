// SPDX-License-Identifier: BSD-3-Clause
// Property-based tests for frameworks: on every shipped framework example and on seeded random
// planar and spatial trusses, the counts (rank, mechanisms, self-stresses) do not change when
// nodes and elements are renamed and listed in another order, and on random trusses also not
// under a rigid motion or a change of length unit (x1e-3, x1e3).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <random>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "support/sanitizer_sample.hpp"

namespace kinestat::framework {
namespace {

struct Counts {
  Eigen::Index m, n, rank, mechanisms, self_stresses;
  bool operator==(const Counts&) const = default;
};

Counts counts_of(const FrameworkModel& model) {
  const FrameworkResult a = analyse_framework(model);
  return {a.m, a.n, a.rank, a.mechanisms, a.self_stresses};
}

std::ostream& operator<<(std::ostream& out, const Counts& c) {
  return out << c.m << "x" << c.n << " rank " << c.rank << " mechanisms " << c.mechanisms << " self-stresses " << c.self_stresses;
}

// Nodes listed in reverse and renamed, elements listed in reverse and renamed.
FrameworkModel renamed_and_reordered(FrameworkModel model) {
  const std::size_t n = model.nodes.size();
  std::reverse(model.nodes.begin(), model.nodes.end());
  for (auto& node : model.nodes) node.name = "node_" + node.name;
  for (auto& element : model.elements) {
    for (auto& index : element.nodes) index = n - 1 - index;
    element.name = "element_" + element.name;
  }
  std::reverse(model.elements.begin(), model.elements.end());
  return model;
}

FrameworkModel moved(FrameworkModel model, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& shift, double scale) {
  for (auto& node : model.nodes) {
    node.position = scale * (rotation * node.position) + shift;
    if (node.triad) node.triad = rotation * *node.triad;
  }
  for (auto& element : model.elements) element.frame = rotation * element.frame;
  return model;
}

// A random truss: nodes on a jittered grid, bars between random pairs of distinct nodes,
// some nodes fully supported.
FrameworkModel random_truss(std::mt19937& rng, int dimension) {
  FrameworkModel model;
  model.dimension = dimension;
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::uniform_int_distribution<int> count(4, 9);
  const int nodes = count(rng);
  for (int i = 0; i < nodes; ++i) {
    Node node;
    node.name = "n" + std::to_string(i);
    node.position = {i % 3 + jitter(rng), i / 3 + jitter(rng), dimension == 3 ? jitter(rng) + (i % 2) : 0.0};
    if (i < dimension - 1) node.roles.fill(CoordinateRole::fixed);  // supports
    model.nodes.push_back(node);
  }
  std::uniform_int_distribution<int> pick(0, nodes - 1);
  const int bars = nodes * (dimension == 3 ? 3 : 2) - 1 + std::uniform_int_distribution<int>(-2, 2)(rng);
  for (int b = 0; b < bars; ++b) {
    Element element;
    element.name = "e" + std::to_string(b);
    std::size_t p = static_cast<std::size_t>(pick(rng)), q = p;
    while (q == p) q = static_cast<std::size_t>(pick(rng));
    element.nodes = {p, q};
    element.roles = {DeformationRole::fixed};
    model.elements.push_back(element);
  }
  return model;
}

TEST(FrameworkProperties, EveryExampleUnderRenamingAndReordering) {
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(KINESTAT_SOURCE_DIR) + "/examples")) {
    if (entry.path().extension() != ".yaml") continue;
    const auto file = io::YamlFile::load(entry.path().string());
    if (io::model_kind(file) != "framework") continue;
    SCOPED_TRACE(entry.path().filename().string());
    const FrameworkModel model = io::read_framework_model(file);
    EXPECT_EQ(counts_of(renamed_and_reordered(model)), counts_of(model));
    ++checked;
  }
  EXPECT_GE(checked, 10);
}

TEST(FrameworkProperties, RandomTrusses) {
  const Eigen::Matrix3d spatial_rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Matrix3d planar_rotation = Eigen::AngleAxisd(-1.1, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  // Under AddressSanitizer the first quarter of the seeds, both dimensions (support/sanitizer_sample.hpp).
  for (int seed = 0; seed < testing::sampled_seed_count(150); ++seed) {
    std::mt19937 rng(static_cast<unsigned>(seed));
    const int dimension = seed % 2 == 0 ? 2 : 3;
    const FrameworkModel model = random_truss(rng, dimension);
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Counts expected = counts_of(model);
    EXPECT_EQ(expected.self_stresses - expected.mechanisms, expected.m - expected.n);
    EXPECT_EQ(counts_of(renamed_and_reordered(model)), expected) << "renamed";
    const Eigen::Matrix3d& rotation = dimension == 2 ? planar_rotation : spatial_rotation;
    const Eigen::Vector3d shift = dimension == 2 ? Eigen::Vector3d(3, -2, 0) : Eigen::Vector3d(3, -2, 5);
    EXPECT_EQ(counts_of(moved(model, rotation, shift, 1.0)), expected) << "rigid motion";
    // Far from the origin (issue 12): 1000 times its size away, coordinates at full double precision.
    double size = 0;
    for (const auto& a : model.nodes)
      for (const auto& b : model.nodes) size = std::max(size, (a.position - b.position).norm());
    const Eigen::Vector3d direction = dimension == 2 ? Eigen::Vector3d(0.8, -0.6, 0) : Eigen::Vector3d(0.48, -0.6, 0.64);
    EXPECT_EQ(counts_of(moved(model, rotation, 1000.0 * size * direction, 1.0)), expected) << "1000 sizes away";
    EXPECT_EQ(counts_of(moved(model, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), 1e3)), expected) << "x1e3";
    EXPECT_EQ(counts_of(moved(model, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), 1e-3)), expected) << "x1e-3";
  }
}

}  // namespace
}  // namespace kinestat::framework
