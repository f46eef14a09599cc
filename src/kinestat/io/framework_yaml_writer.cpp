// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/framework_yaml_writer.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace kinestat::io {

using framework::CoordinateRole;
using framework::DeformationRole;
using framework::Element;
using framework::ElementType;
using framework::FrameworkModel;

namespace {

// A YAML double-quoted scalar: JSON's string escapes are valid YAML.
std::string quoted(const std::string& text) { return nlohmann::json(text).dump(); }

// Shortest text that reads back as the same double.
std::string number(double value) { return fmt::format("{}", value == 0.0 ? 0.0 : value); }

std::string vector(const Eigen::Vector3d& v, int size) {
  std::string out = "[";
  for (int i = 0; i < size; ++i) out += (i ? ", " : "") + number(v(i));
  return out + "]";
}

std::string list(const std::vector<std::string>& items) {
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + items[i];
  return out + "]";
}

std::string type_word(ElementType type) {
  switch (type) {
    case ElementType::truss: return "truss";
    case ElementType::beam: return "beam";
    case ElementType::rigid_body: return "rigid_body";
  }
  return "truss";
}

// `materials:`, `sections:` and `defaults:` as they were read (sections in their given shape).
std::string elastic_data_yaml(const FrameworkModel& model) {
  std::string out;
  if (!model.materials.empty()) out += "materials:\n";
  for (const framework::Material& m : model.materials) {
    out += fmt::format("  {}: {{E: {}", quoted(m.name), number(m.youngs_modulus));
    if (m.shear_modulus) out += ", G: " + number(*m.shear_modulus);
    if (m.poisson) out += ", poisson: " + number(*m.poisson);
    if (m.density) out += ", density: " + number(*m.density);
    out += "}\n";
  }
  if (!model.sections.empty()) out += "sections:\n";
  for (const framework::Section& section : model.sections) {
    out += "  " + quoted(section.name) + ": ";
    switch (section.shape) {
      case framework::SectionShape::circle: out += fmt::format("{{circle: {}}}\n", number(section.dimensions[0])); break;
      case framework::SectionShape::rectangle:
        out += fmt::format("{{rectangle: [{}, {}]}}\n", number(section.dimensions[0]), number(section.dimensions[1]));
        break;
      case framework::SectionShape::area_only: out += fmt::format("{{area: {}}}\n", number(section.area)); break;
      case framework::SectionShape::explicit_values:
        out += fmt::format("{{area: {}, Iy: {}, Iz: {}, J: {}}}\n", number(section.area), number(section.iy), number(section.iz),
                           number(section.torsion));
        break;
      case framework::SectionShape::rigidities:
        out += fmt::format("{{EA: {}, EIy: {}, EIz: {}, GJ: {}", number(section.area), number(section.iy), number(section.iz),
                           number(section.torsion));
        if (section.mass_per_length > 0.0) out += ", mass_per_length: " + number(section.mass_per_length);
        out += "}\n";
        break;
    }
  }
  if (model.default_material || model.default_section) {
    out += "defaults: {";
    if (model.default_material) out += "material: " + quoted(model.materials[*model.default_material].name);
    if (model.default_material && model.default_section) out += ", ";
    if (model.default_section) out += "section: " + quoted(model.sections[*model.default_section].name);
    out += "}\n";
  }
  return out;
}

}  // namespace

std::string framework_yaml(const FrameworkModel& model, const std::vector<std::string>& comments) {
  std::string out;
  for (const auto& c : comments) out += "# " + c + "\n";
  out += "kinestat: 1\nkind: framework\n";
  if (!model.name.empty()) out += "name: " + quoted(model.name) + "\n";
  out += model.dimension == 2 ? "dimension: planar\n" : "dimension: spatial\n";
  if (!model.units.empty()) out += "units: " + quoted(model.units) + "\n";
  out += "nodes:\n";
  for (const auto& node : model.nodes) {
    if (node.triad) {
      const Eigen::Matrix3d& t = *node.triad;
      out += fmt::format("  {}: {{position: {}, orientation: [{}, {}, {}]}}\n", quoted(node.name), vector(node.position, 3),
                         vector(t.col(0), 3), vector(t.col(1), 3), vector(t.col(2), 3));
    } else {
      out += fmt::format("  {}: {}\n", quoted(node.name), vector(node.position, model.dimension));
    }
  }
  for (const auto& [role, key] : {std::pair{CoordinateRole::fixed, "supports"}, std::pair{CoordinateRole::independent, "independent"}}) {
    std::string block;
    for (const auto& node : model.nodes) {
      std::vector<std::string> slots;
      for (int s : framework::node_slots(model.dimension, node))
        if (node.roles[static_cast<std::size_t>(s)] == role) slots.emplace_back(framework::kSlotNames[static_cast<std::size_t>(s)]);
      if (!slots.empty()) block += fmt::format("  {}: {}\n", quoted(node.name), list(slots));
    }
    if (!block.empty()) out += std::string(key) + ":\n" + block;
  }
  out += elastic_data_yaml(model);
  // No element (a bar table of nodes alone): "elements:" with nothing after it reads back as null.
  out += model.elements.empty() ? "elements: []\n" : "elements:\n";
  for (const Element& element : model.elements) {
    std::vector<std::string> nodes;
    for (std::size_t n : element.nodes) nodes.push_back(quoted(model.nodes[n].name));
    out += fmt::format("  - {{name: {}, type: {}, nodes: {}", quoted(element.name), type_word(element.type), list(nodes));
    // The whole triad, so that the frame reads back bit for bit (a frame read from a rounded
    // z axis is orthonormal only to the rounding of that axis).
    if (element.type == ElementType::beam && model.dimension == 3) {
      const Eigen::Matrix3d& f = element.frame;
      out += fmt::format(", orientation: [{}, {}, {}]", vector(f.col(0), 3), vector(f.col(1), 3), vector(f.col(2), 3));
    }
    if (element.torsion_coupling != 0.0) out += ", torsion_coupling: " + number(element.torsion_coupling);
    if (element.material) out += ", material: " + quoted(model.materials[*element.material].name);
    if (element.section) out += ", section: " + quoted(model.sections[*element.section].name);
    const auto names = framework::deformation_names(model, element);
    for (const auto& [role, key] : {std::pair{DeformationRole::released, "released"}, std::pair{DeformationRole::independent, "independent"}}) {
      std::vector<std::string> chosen;
      for (std::size_t d = 0; d < element.roles.size(); ++d)
        if (element.roles[d] == role) chosen.push_back(quoted(names[d]));
      if (!chosen.empty()) out += fmt::format(", {}: {}", key, list(chosen));
    }
    out += "}\n";
  }
  if (!model.masses.empty()) {
    out += "masses:\n";
    for (const framework::NodeMass& m : model.masses) {
      if (m.inertia) {
        out += fmt::format("  {}: {{mass: {}, inertia: {}}}\n", quoted(model.nodes[m.node].name), number(m.mass), vector(*m.inertia, 3));
      } else {
        out += fmt::format("  {}: {}\n", quoted(model.nodes[m.node].name), number(m.mass));
      }
    }
  }
  return out;
}

}  // namespace kinestat::io
