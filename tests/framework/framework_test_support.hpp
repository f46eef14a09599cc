// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Helpers shared by the framework tests: load an example, transform a model rigidly or by
// scaling, and find rows/columns of D(c) by label.

#include <Eigen/Geometry>

#include <string>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/report/framework_report.hpp"

namespace kinestat::framework::testing {

inline std::string example_path(const std::string& name) { return std::string(KINESTAT_SOURCE_DIR) + "/examples/" + name; }

inline FrameworkModel load_example(const std::string& name) {
  return io::read_framework_model(io::YamlFile::load(example_path(name)));
}

inline FrameworkModel parse_model(const std::string& text) {
  return io::read_framework_model(io::YamlFile::parse("test.yaml", text));
}

/// x -> scale * rotation * x + shift, triads and element frames rotated along.
inline FrameworkModel transformed(FrameworkModel model, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& shift,
                                  double scale) {
  for (Node& node : model.nodes) {
    node.position = scale * (rotation * node.position) + shift;
    if (node.triad) node.triad = rotation * *node.triad;
  }
  for (Element& element : model.elements) element.frame = rotation * element.frame;
  return model;
}

/// A generic 3-D rotation (no special angles).
inline Eigen::Matrix3d generic_rotation() {
  return (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) * Eigen::AngleAxisd(-1.1, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

/// A rotation about z (keeps planar models planar).
inline Eigen::Matrix3d planar_rotation() { return Eigen::AngleAxisd(0.9, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }

inline Eigen::Index column_of(const FrameworkModel& model, const FrameworkResult& a, const std::string& label) {
  for (Eigen::Index j = 0; j < a.n; ++j)
    if (report::framework_column_label(model, a, j) == label) return j;
  return -1;
}

inline Eigen::Index row_of(const FrameworkModel& model, const FrameworkResult& a, const std::string& label) {
  for (Eigen::Index i = 0; i < a.m; ++i)
    if (report::framework_row_label(model, a, i) == label) return i;
  return -1;
}

}  // namespace kinestat::framework::testing
