// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/framework_reader.hpp"

#include "kinestat/io/model_vocabulary.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <cstdint>
#include <functional>
#include <set>
#include <string_view>

namespace kinestat::io {

using framework::CoordinateRole;
using framework::DeformationRole;
using framework::Element;
using framework::ElementType;
using framework::FrameworkModel;
using framework::Node;

namespace {

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

// Names to indices by open addressing (linear probing, at most half full): no allocation per
// name. The table holds indices only; `name_of(index)` gives the name stored elsewhere (in the
// model), so the table stays valid while the model's vectors grow.
class FrameworkNameIndex {
 public:
  static constexpr std::size_t kAbsent = static_cast<std::size_t>(-1);

  /// The index whose name is `name`, or kAbsent.
  template <typename NameOf>
  std::size_t find(std::string_view name, const NameOf& name_of) const {
    if (slots_.empty()) return kAbsent;
    for (std::size_t s = std::hash<std::string_view>{}(name) & mask_;; s = (s + 1) & mask_) {
      const std::uint32_t held = slots_[s];
      if (held == 0) return kAbsent;
      if (name_of(held - 1) == name) return held - 1;
    }
  }

  /// Adds `index` (its name not held yet). `expected`: how many names the table will hold.
  template <typename NameOf>
  void insert(std::size_t index, std::size_t expected, const NameOf& name_of) {
    if (2 * (size_ + 1) > slots_.size()) {
      std::size_t capacity = 16;
      while (capacity < 2 * std::max(expected, size_ + 1)) capacity <<= 1;
      std::vector<std::uint32_t> old(capacity, 0);
      old.swap(slots_);
      mask_ = capacity - 1;
      for (const std::uint32_t held : old)
        if (held != 0) place(held - 1, name_of(held - 1));
    }
    place(index, name_of(index));
    ++size_;
  }

 private:
  void place(std::size_t index, std::string_view name) {
    std::size_t s = std::hash<std::string_view>{}(name) & mask_;
    while (slots_[s] != 0) s = (s + 1) & mask_;
    slots_[s] = static_cast<std::uint32_t>(index + 1);
  }
  std::vector<std::uint32_t> slots_;  ///< 1 + index, 0 for an empty slot
  std::size_t mask_ = 0, size_ = 0;
};

class FrameworkReader {
 public:
  explicit FrameworkReader(const YamlFile& file) : file_(file) {}

  FrameworkModel read() {
    const TreeNode& root = file_.root();
    file_.check_keys(root, "the framework model",
                     {"kinestat", kSchemaKey, "kind", "name", "description", "dimension", "units", "nodes", "supports", "independent", "inputs",
                      "elements", "materials", "sections", "defaults", "masses"});
    if (auto name = file_.optional(root, "name"); name.defined()) model_.name = file_.string(name, "'name'");
    model_.dimension = read_planar(file_, root, "framework", false) ? 2 : 3;
    model_.units = read_units(file_, root);
    read_nodes(file_.required(root, "nodes", "the framework model"));
    // Elastic data (issue 38) before the elements, which name it.
    if (auto materials = file_.optional(root, "materials"); materials.defined()) read_materials(materials);
    if (auto sections = file_.optional(root, "sections"); sections.defined()) read_sections(sections);
    if (auto defaults = file_.optional(root, "defaults"); defaults.defined()) read_defaults(defaults);
    const TreeNode elements = file_.required(root, "elements", "the framework model");
    file_.expect_sequence(elements, "'elements'");
    element_nodes_.clear();
    model_.elements.reserve(elements.size());
    orientations_.reserve(elements.size());
    element_nodes_.reserve(elements.size());
    for (const auto& item : elements.items()) read_element(item, elements.size());
    for (std::size_t e = 0; e < model_.elements.size(); ++e) set_frame(e);
    if (auto supports = file_.optional(root, "supports"); supports.defined()) read_supports(supports);
    // The intended motions: `inputs:`, the key every kind uses, or the seed's `independent:`.
    const TreeNode independent = file_.optional(root, "independent"), inputs = file_.optional(root, "inputs");
    if (independent.defined() && inputs.defined())
      file_.fail(inputs, "'inputs' and 'independent' both declare the intended motions: give one of them");
    if (inputs.defined()) read_independent(inputs);
    else if (independent.defined()) read_independent(independent);
    if (auto masses = file_.optional(root, "masses"); masses.defined()) read_masses(masses);
    return std::move(model_);
  }

 private:
  // The text of a non-empty scalar name, without a copy; otherwise YamlFile::string's error.
  std::string_view name_text(const TreeNode& item, const char* what) const {
    if (item.is_scalar() && !item.scalar().empty()) return item.scalar();
    static_cast<void>(file_.string(item, what));  // throws
    return {};
  }

  std::size_t find_node(std::string_view name) const {
    return node_index_.find(name, [this](std::size_t n) -> std::string_view { return model_.nodes[n].name; });
  }
  // True when an element read before has the name `name`. Only the names given in the file are
  // in element_index_: an element without a name is called by its position, so "k" can only
  // be element k among those (checked directly) or a given name.
  bool element_name_taken(std::string_view name) const {
    std::size_t position = 0;
    const bool canonical = !name.empty() && name[0] != '0' && name.size() <= 9 &&
                           std::all_of(name.begin(), name.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
    if (canonical) {
      for (char ch : name) position = 10 * position + static_cast<std::size_t>(ch - '0');
      if (position <= model_.elements.size() && model_.elements[position - 1].name == name) return true;
    }
    return element_index_.find(name, [this](std::size_t e) -> std::string_view { return model_.elements[e].name; }) !=
           FrameworkNameIndex::kAbsent;
  }

  Eigen::Vector3d vector3(const TreeNode& node, std::string_view what) const {
    const auto values = file_.numbers(node, what, {3});
    return {values[0].value, values[1].value, values[2].value};
  }

  // A triad given as three rows: the x, y and z axes in global coordinates. Returns the
  // matrix whose columns are those axes.
  Eigen::Matrix3d triad(const TreeNode& node, std::string_view what) const {
    file_.expect_sequence(node, what);
    if (node.size() != 3) file_.fail(node, fmt::format("{} must be three axes [[x], [y], [z]], found {} entries", what, node.size()));
    Eigen::Matrix3d axes;
    for (std::size_t i = 0; i < 3; ++i) axes.col(static_cast<Eigen::Index>(i)) = vector3(node[i], what);
    const double deviation = (axes.transpose() * axes - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (!(deviation <= kOrientationTolerance)) {
      file_.fail(node, fmt::format("{} is not orthonormal: the axes deviate from unit length or right angles by {:.3g}",
                                   what, deviation));
    }
    if (axes.determinant() < 0) file_.fail(node, fmt::format("{} is left-handed: z must be x × y", what));
    return axes;
  }

  void read_nodes(const TreeNode& nodes) {
    file_.expect_map(nodes, "'nodes'");
    if (nodes.size() == 0) file_.fail(nodes, "'nodes' is empty: a framework needs at least one node");
    model_.nodes.reserve(nodes.size());
    const auto dimension = static_cast<std::size_t>(model_.dimension);
    // Messages are prepared only when an error is raised: the success path of a node formats nothing.
    for (const auto& entry : nodes.entries()) {
      const std::string_view name = name_text(entry.first, "a node name");
      if (find_node(name) != FrameworkNameIndex::kAbsent) file_.fail(entry.first, fmt::format("duplicate node name '{}'", name));
      Node node;
      node.name = std::string(name);
      const bool detailed = entry.second.is_map();
      if (detailed && !file_.keys_allowed(entry.second, {"position", "orientation"}))
        file_.check_keys(entry.second, fmt::format("node '{}'", name), {"position", "orientation"});
      TreeNode position = detailed ? entry.second["position"] : entry.second;
      if (!position.defined()) position = file_.required(entry.second, "position", fmt::format("node '{}'", name));
      if (detailed) {
        if (auto orientation = file_.optional(entry.second, "orientation"); orientation.defined()) {
          if (model_.dimension == 2) file_.fail(orientation, "a planar node has no orientation: its rotation is about z");
          node.triad = triad(orientation, fmt::format("the orientation of node '{}'", name));
          node.rotational = true;
        }
      }
      double values[3] = {0.0, 0.0, 0.0};
      if (!file_.plain_numbers(position, dimension, values)) {
        const auto exact = file_.numbers(position, fmt::format("the position of node '{}'", name), {dimension});
        for (std::size_t i = 0; i < exact.size(); ++i) values[i] = exact[i].value;
      }
      for (std::size_t i = 0; i < dimension; ++i) node.position(static_cast<Eigen::Index>(i)) = values[i];
      model_.nodes.push_back(std::move(node));
      node_index_.insert(model_.nodes.size() - 1, nodes.size(),
                         [this](std::size_t n) -> std::string_view { return model_.nodes[n].name; });
    }
    length_ = framework::characteristic_length(model_);
  }

  std::size_t node_index(const TreeNode& item) const {
    const std::string_view name = name_text(item, "a node name");
    const std::size_t found = find_node(name);
    if (found == FrameworkNameIndex::kAbsent) file_.fail(item, fmt::format("unknown node '{}'", name));
    return found;
  }

  // Deformation names and the groups a `released:` or `independent:` list may use.
  std::map<std::string, std::vector<std::size_t>> deformation_groups(const Element& element) const {
    std::map<std::string, std::vector<std::size_t>> groups;
    const auto names = framework::deformation_names(model_, element);
    for (std::size_t k = 0; k < names.size(); ++k) groups[names[k]] = {k};
    if (element.type == ElementType::beam) {
      for (std::size_t k = 0; k < names.size(); ++k) groups[fmt::format("e{}", k + 1)] = {k};
      if (model_.dimension == 3) {
        groups["bending"] = {2, 3, 4, 5};
        groups["bending_xz"] = {2, 3};
        groups["bending_xy"] = {4, 5};
      } else {
        groups["bending"] = {1, 2};
      }
    } else if (element.type == ElementType::truss) {
      groups["e1"] = {0};
    } else {
      const std::size_t per_node = model_.dimension == 2 ? 3 : 6;
      for (std::size_t k = 1; k < element.nodes.size(); ++k)
        for (std::size_t i = 0; i < per_node; ++i) groups[model_.nodes[element.nodes[k]].name].push_back((k - 1) * per_node + i);
    }
    return groups;
  }

  void read_roles(const TreeNode& list, Element& element, DeformationRole role, std::string_view what) {
    file_.expect_sequence(list, what);
    const auto groups = deformation_groups(element);
    for (const auto& item : list.items()) {
      const std::string name = file_.string(item, "a deformation name");
      const auto found = groups.find(name);
      if (found == groups.end()) {
        file_.fail(item, fmt::format("element '{}' ({}) has no deformation '{}'; it has: {}", element.name,
                                     type_name(element.type), name,
                                     join(framework::deformation_names(model_, element))));
      }
      for (std::size_t k : found->second) {
        // An independent deformation is also released; `released:` never demotes it.
        if (role == DeformationRole::released && element.roles[k] == DeformationRole::independent) continue;
        element.roles[k] = role;
      }
    }
  }

  std::string type_name(ElementType type) const {
    switch (type) {
      case ElementType::truss: return model_.dimension == 2 ? "planar truss" : "truss";
      case ElementType::beam: return model_.dimension == 2 ? "planar beam" : "beam";
      case ElementType::rigid_body: return "rigid body";
    }
    return "element";
  }

  // `count`: the number of elements in the file. Messages are prepared only when an error is
  // raised: the success path of an element formats nothing.
  void read_element(const TreeNode& item, std::size_t count) {
    const auto label = [this] { return fmt::format("element {}", model_.elements.size() + 1); };
    if (!file_.keys_allowed(item, {"type", "name", "nodes", "released", "independent", "orientation", "torsion_coupling", "material",
                                   "section"})) {
      file_.check_keys(item, label(),
                       {"type", "name", "nodes", "released", "independent", "orientation", "torsion_coupling", "material", "section"});
    }
    Element element;
    element.name = std::to_string(model_.elements.size() + 1);
    const TreeNode given_name = file_.optional(item, "name");
    if (given_name.defined()) element.name = file_.string(given_name, "an element name");
    if (element_name_taken(element.name)) file_.fail(item, fmt::format("duplicate element name '{}'", element.name));
    TreeNode type = item["type"];
    if (!type.defined()) type = file_.required(item, "type", label());
    const std::string_view type_text = name_text(type, "an element type");
    if (type_text == "truss") element.type = ElementType::truss;
    else if (type_text == "beam") element.type = ElementType::beam;
    else if (type_text == "rigid_body") element.type = ElementType::rigid_body;
    else file_.fail(type, fmt::format("unknown element type '{}'; expected truss, beam or rigid_body", type_text));

    TreeNode nodes = item["nodes"];
    if (!nodes.defined()) nodes = file_.required(item, "nodes", label());
    if (!nodes.is_sequence()) file_.expect_sequence(nodes, fmt::format("the nodes of element '{}'", element.name));
    element.nodes.reserve(nodes.size());
    for (const auto& n : nodes.items()) {
      const std::size_t index = node_index(n);
      if (std::find(element.nodes.begin(), element.nodes.end(), index) != element.nodes.end())
        file_.fail(n, fmt::format("node '{}' appears twice in element '{}'", model_.nodes[index].name, element.name));
      element.nodes.push_back(index);
    }
    if (element.type == ElementType::rigid_body) {
      if (element.nodes.size() < 2) file_.fail(nodes, "a rigid body needs at least two nodes (the first is its reference node)");
    } else if (element.nodes.size() != 2) {
      file_.fail(nodes, fmt::format("a {} connects exactly two nodes, found {}", type_text, element.nodes.size()));
    } else {
      const double l = (model_.nodes[element.nodes[1]].position - model_.nodes[element.nodes[0]].position).norm();
      if (!(l > kCoincident * length_)) {
        file_.fail(nodes, fmt::format("zero-length element '{}': nodes '{}' and '{}' coincide", element.name,
                                      model_.nodes[element.nodes[0]].name, model_.nodes[element.nodes[1]].name));
      }
    }
    if (element.type != ElementType::truss)
      for (std::size_t n : element.nodes) model_.nodes[n].rotational = true;

    if (auto c = file_.optional(item, "torsion_coupling"); c.defined()) {
      if (element.type != ElementType::beam || model_.dimension != 3)
        file_.fail(c, "'torsion_coupling' applies to spatial beams only");
      element.torsion_coupling = file_.number(c, "'torsion_coupling'").value;
    }
    element.roles.assign(framework::deformation_count(model_.dimension, element), DeformationRole::fixed);
    if (auto independent = file_.optional(item, "independent"); independent.defined())
      read_roles(independent, element, DeformationRole::independent, "'independent' deformations");
    if (auto released = file_.optional(item, "released"); released.defined())
      read_roles(released, element, DeformationRole::released, "'released' deformations");
    if (auto material = file_.optional(item, "material"); material.defined()) {
      if (element.type == ElementType::rigid_body) file_.fail(material, "a rigid body takes no material: it stays rigid");
      element.material = named(material, model_.materials, "material");
    }
    if (auto section = file_.optional(item, "section"); section.defined()) {
      if (element.type == ElementType::rigid_body) file_.fail(section, "a rigid body takes no section: it stays rigid");
      element.section = named(section, model_.sections, "section");
    }
    orientations_.push_back(file_.optional(item, "orientation"));
    element_nodes_.push_back(nodes);
    model_.elements.push_back(std::move(element));
    if (given_name.defined()) {
      element_index_.insert(model_.elements.size() - 1, count,
                            [this](std::size_t e) -> std::string_view { return model_.elements[e].name; });
    }
  }

  // The element triad of a beam (eq 4): local x from p to q, y and z across the section.
  void set_frame(std::size_t e) {
    Element& element = model_.elements[e];
    const TreeNode& orientation = orientations_[e];
    if (element.type != ElementType::beam) {
      if (orientation.defined()) file_.fail(orientation, "only beams have an orientation");
      return;
    }
    const Node& p = model_.nodes[element.nodes[0]];
    const Eigen::Vector3d x = (model_.nodes[element.nodes[1]].position - p.position).normalized();
    if (model_.dimension == 2) {
      if (orientation.defined()) file_.fail(orientation, "a planar beam takes its orientation from the plane (local z = global z)");
      element.frame << x, Eigen::Vector3d::UnitZ().cross(x), Eigen::Vector3d::UnitZ();
      return;
    }
    const std::string what = fmt::format("the orientation of element '{}'", element.name);
    if (orientation.defined() && orientation.is_map()) {
      file_.check_keys(orientation, what, {"y", "z"});
      if (orientation.size() != 1) file_.fail(orientation, fmt::format("{} gives exactly one of y or z", what));
      const bool is_y = file_.optional(orientation, "y").defined();
      const TreeNode axis_node = is_y ? file_.optional(orientation, "y") : file_.optional(orientation, "z");
      const Eigen::Vector3d axis = vector3(axis_node, what);
      if (!(axis.norm() > 0)) file_.fail(axis_node, fmt::format("{}: the axis is the zero vector", what));
      const Eigen::Vector3d unit = axis.normalized();
      const double cosine = unit.dot(x);
      if (!(std::abs(cosine) <= kOrientationTolerance)) {
        file_.fail(axis_node, fmt::format("{}: local {} must be perpendicular to the element axis from '{}' to '{}' (cosine {:.3g})",
                                          what, is_y ? "y" : "z", p.name, model_.nodes[element.nodes[1]].name, cosine));
      }
      if (is_y) element.frame << x, unit, x.cross(unit);
      else element.frame << x, unit.cross(x), unit;
      return;
    }
    if (orientation.defined()) {
      element.frame = triad(orientation, what);
      check_along(element.frame.col(0), x, orientation, what, element);
      return;
    }
    if (p.triad) {
      check_along(p.triad->col(0), x, element_nodes_[e], fmt::format("the orientation of node '{}'", p.name), element);
      element.frame = *p.triad;
      return;
    }
    // Default: local z is the global z axis made perpendicular to the element (global x for
    // elements along z); see docs/framework.md.
    const Eigen::Vector3d reference = std::abs(x.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
    const Eigen::Vector3d z = (reference - reference.dot(x) * x).normalized();
    element.frame << x, z.cross(x), z;
  }

  void check_along(const Eigen::Vector3d& axis, const Eigen::Vector3d& x, const TreeNode& where, const std::string& what,
                   const Element& element) const {
    if (!((axis - x).cwiseAbs().maxCoeff() <= kOrientationTolerance)) {
      file_.fail(where, fmt::format("{}: its x axis must point along element '{}' from '{}' to '{}' (give the element an "
                                    "orientation)", what, element.name, model_.nodes[element.nodes[0]].name,
                                    model_.nodes[element.nodes[1]].name));
    }
  }

  // Slots named in a support or independent list.
  std::vector<int> slots(const TreeNode& value, const Node& node, bool allow_keywords) const {
    const std::vector<int> available = framework::node_slots(model_.dimension, node);
    if (allow_keywords && value.is_scalar()) {
      const std::string_view word = value.scalar();
      if (word == "fixed") return available;
      if (word == "pinned") {
        std::vector<int> translations;
        for (int s : available)
          if (framework::is_translation(s)) translations.push_back(s);
        return translations;
      }
      file_.fail(value, fmt::format("unknown support '{}'; expected fixed, pinned or a list of coordinates", word));
    }
    file_.expect_sequence(value, fmt::format("the coordinates of node '{}'", node.name));
    std::vector<int> result;
    for (const auto& item : value.items()) {
      const std::string name = file_.string(item, "a coordinate name");
      const auto found = std::find(framework::kSlotNames.begin(), framework::kSlotNames.end(), name);
      const int slot = found == framework::kSlotNames.end() ? -1 : static_cast<int>(found - framework::kSlotNames.begin());
      if (slot < 0) file_.fail(item, fmt::format("unknown coordinate '{}'; expected x, y, z, rx, ry or rz", name));
      if (std::find(available.begin(), available.end(), slot) == available.end()) {
        if (model_.dimension == 2 && (slot == 2 || slot == 3 || slot == 4))
          file_.fail(item, fmt::format("a planar model has no coordinate '{}'", name));
        file_.fail(item, fmt::format("node '{}' has no rotational coordinate '{}': only nodes of beams, rigid bodies or with an "
                                     "orientation rotate", node.name, name));
      }
      result.push_back(slot);
    }
    return result;
  }

  // A number of the elastic data: checked as every number is, and then the double nearest to
  // its decimal (not rounded toward zero as coordinates are), so that the shortest text the
  // writer gives reads back as the same double.
  double elastic_number(const TreeNode& node, const std::string& what) const {
    const double checked = file_.number(node, what).value;
    if (!node.is_scalar()) return checked;
    const std::string_view text = node.scalar();
    double nearest = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), nearest);
    return error == std::errc() && end == text.data() + text.size() && std::isfinite(nearest) ? nearest : checked;
  }

  // A positive (or, with `allow_zero`, non-negative) finite number.
  double positive(const TreeNode& node, const std::string& what, bool allow_zero = false) const {
    const double value = elastic_number(node, what);
    if (!(value > 0.0 || (allow_zero && value == 0.0)))
      file_.fail(node, fmt::format("{} must be {}, found {}", what, allow_zero ? "zero or positive" : "positive", value));
    return value;
  }

  void read_materials(const TreeNode& materials) {
    file_.expect_map(materials, "'materials'");
    for (const auto& entry : materials.entries()) {
      framework::Material material;
      material.name = file_.string(entry.first, "a material name");
      for (const auto& other : model_.materials)
        if (other.name == material.name) file_.fail(entry.first, fmt::format("duplicate material name '{}'", material.name));
      const std::string what = fmt::format("material '{}'", material.name);
      file_.expect_map(entry.second, what);
      file_.check_keys(entry.second, what, {"E", "G", "poisson", "density"});
      material.youngs_modulus = positive(file_.required(entry.second, "E", what), what + ": E");
      const TreeNode g = file_.optional(entry.second, "G"), poisson = file_.optional(entry.second, "poisson");
      if (g.defined() && poisson.defined()) file_.fail(poisson, fmt::format("{} gives both G and poisson: give one of them", what));
      if (g.defined()) material.shear_modulus = positive(g, what + ": G");
      if (poisson.defined()) {
        const double nu = elastic_number(poisson, what + ": poisson");
        if (!(nu > -1.0 && nu < 0.5)) file_.fail(poisson, fmt::format("{}: poisson must be between -1 and 0.5, found {}", what, nu));
        material.poisson = nu;
      }
      if (auto density = file_.optional(entry.second, "density"); density.defined())
        material.density = positive(density, what + ": density", true);
      model_.materials.push_back(std::move(material));
    }
  }

  void read_sections(const TreeNode& sections) {
    file_.expect_map(sections, "'sections'");
    for (const auto& entry : sections.entries()) {
      framework::Section section;
      section.name = file_.string(entry.first, "a section name");
      for (const auto& other : model_.sections)
        if (other.name == section.name) file_.fail(entry.first, fmt::format("duplicate section name '{}'", section.name));
      const std::string what = fmt::format("section '{}'", section.name);
      const TreeNode& value = entry.second;
      file_.expect_map(value, what);
      file_.check_keys(value, what, {"area", "circle", "rectangle", "Iy", "Iz", "J", "EA", "EIy", "EIz", "GJ", "mass_per_length"});
      if (file_.optional(value, "EA").defined()) {
        model_.sections.push_back(rigidity_section(std::move(section), value, what));
        continue;
      }
      const TreeNode circle = file_.optional(value, "circle"), rectangle = file_.optional(value, "rectangle");
      const TreeNode area = file_.optional(value, "area");
      const bool explicit_set = area.defined() && value.size() == 4 && file_.optional(value, "Iy").defined() &&
                                file_.optional(value, "Iz").defined() && file_.optional(value, "J").defined();
      const bool single = value.size() == 1 && (circle.defined() || rectangle.defined() || area.defined());
      if (!explicit_set && !single) {
        file_.fail(value, fmt::format("{} must be one of {{area}}, {{circle: DIAMETER}}, {{rectangle: [WIDTH, THICKNESS]}} or "
                                      "{{area, Iy, Iz, J}}", what));
      }
      if (circle.defined()) {
        section.shape = framework::SectionShape::circle;
        section.dimensions[0] = positive(circle, what + ": the circle's diameter");
      } else if (rectangle.defined()) {
        section.shape = framework::SectionShape::rectangle;
        static_cast<void>(file_.numbers(rectangle, what + ": rectangle [WIDTH, THICKNESS]", {2}));
        for (std::size_t i = 0; i < 2; ++i) {
          section.dimensions[i] = elastic_number(rectangle[i], what + ": rectangle side");
          if (!(section.dimensions[i] > 0.0)) file_.fail(rectangle[i], fmt::format("{}: the rectangle's sides must be positive", what));
        }
      } else if (value.size() == 4) {
        section.shape = framework::SectionShape::explicit_values;
        section.area = positive(area, what + ": area");
        section.iy = positive(file_.optional(value, "Iy"), what + ": Iy", true);
        section.iz = positive(file_.optional(value, "Iz"), what + ": Iz", true);
        section.torsion = positive(file_.optional(value, "J"), what + ": J", true);
      } else {
        section.shape = framework::SectionShape::area_only;
        section.area = positive(area, what + ": area");
      }
      model_.sections.push_back(framework::completed_section(std::move(section)));
    }
  }

  // A section given by its rigidities {EA, EIy, EIz, GJ[, mass_per_length]} (SPACAR's ESTIFF
  // and EM, docs/stiffness.md): no material needed, no peak stress.
  framework::Section rigidity_section(framework::Section section, const TreeNode& value, const std::string& what) const {
    const TreeNode mass = file_.optional(value, "mass_per_length");
    for (const char* key : {"EIy", "EIz", "GJ"})
      if (!file_.optional(value, key).defined())
        file_.fail(value, fmt::format("{} given by rigidities needs EA, EIy, EIz and GJ (and optionally mass_per_length)", what));
    if (value.size() != (mass.defined() ? 5u : 4u))
      file_.fail(value, fmt::format("{}: rigidities {{EA, EIy, EIz, GJ, mass_per_length}} take no area, circle or rectangle", what));
    section.shape = framework::SectionShape::rigidities;
    section.area = positive(file_.optional(value, "EA"), what + ": EA", true);
    section.iy = positive(file_.optional(value, "EIy"), what + ": EIy", true);
    section.iz = positive(file_.optional(value, "EIz"), what + ": EIz", true);
    section.torsion = positive(file_.optional(value, "GJ"), what + ": GJ", true);
    if (mass.defined()) section.mass_per_length = positive(mass, what + ": mass_per_length", true);
    return section;
  }

  // The index of the material or section named by `item` in `list`.
  template <typename Named>
  std::size_t named(const TreeNode& item, const std::vector<Named>& list, const char* kind) const {
    const std::string name = file_.string(item, fmt::format("a {} name", kind));
    for (std::size_t i = 0; i < list.size(); ++i)
      if (list[i].name == name) return i;
    std::vector<std::string> names;
    for (const auto& entry : list) names.push_back(entry.name);
    file_.fail(item, fmt::format("unknown {} '{}'{}", kind, name,
                                 names.empty() ? fmt::format("; the model has no '{}s'", kind) : "; expected one of: " + join(names)));
  }

  void read_defaults(const TreeNode& defaults) {
    file_.expect_map(defaults, "'defaults'");
    file_.check_keys(defaults, "'defaults'", {"material", "section"});
    if (auto m = file_.optional(defaults, "material"); m.defined()) model_.default_material = named(m, model_.materials, "material");
    if (auto s = file_.optional(defaults, "section"); s.defined()) model_.default_section = named(s, model_.sections, "section");
  }

  void read_masses(const TreeNode& masses) {
    file_.expect_map(masses, "'masses'");
    std::set<std::size_t> seen;
    for (const auto& entry : masses.entries()) {
      framework::NodeMass mass;
      mass.node = node_index(entry.first);
      const Node& node = model_.nodes[mass.node];
      if (!seen.insert(mass.node).second) file_.fail(entry.first, fmt::format("duplicate mass for node '{}'", node.name));
      const std::string what = fmt::format("the mass of node '{}'", node.name);
      if (!entry.second.is_map()) {
        mass.mass = positive(entry.second, what, true);
      } else {
        file_.check_keys(entry.second, what, {"mass", "inertia"});
        mass.mass = positive(file_.required(entry.second, "mass", what), what, true);
        if (auto inertia = file_.optional(entry.second, "inertia"); inertia.defined()) {
          if (!node.rotational)
            file_.fail(inertia, fmt::format("node '{}' has no rotations (only nodes of beams, rigid bodies or with an orientation "
                                            "do): it takes no inertia", node.name));
          static_cast<void>(file_.numbers(inertia, fmt::format("the inertia of node '{}' [Ixx, Iyy, Izz]", node.name), {3}));
          Eigen::Vector3d principal;
          for (std::size_t i = 0; i < 3; ++i) {
            principal(static_cast<Eigen::Index>(i)) = positive(inertia[i], fmt::format("the inertia of node '{}'", node.name), true);
          }
          mass.inertia = principal;
        }
      }
      model_.masses.push_back(std::move(mass));
    }
  }

  void read_supports(const TreeNode& supports) {
    file_.expect_map(supports, "'supports'");
    std::set<std::size_t> seen;
    for (const auto& entry : supports.entries()) {
      const std::size_t n = node_index(entry.first);
      if (!seen.insert(n).second) file_.fail(entry.first, fmt::format("duplicate support for node '{}'", model_.nodes[n].name));
      for (int s : slots(entry.second, model_.nodes[n], true))
        model_.nodes[n].roles[static_cast<std::size_t>(s)] = CoordinateRole::fixed;
    }
  }

  void read_independent(const TreeNode& independent) {
    file_.expect_map(independent, "'independent'");
    std::set<std::size_t> seen;
    for (const auto& entry : independent.entries()) {
      const std::size_t n = node_index(entry.first);
      Node& node = model_.nodes[n];
      if (!seen.insert(n).second) file_.fail(entry.first, fmt::format("duplicate entry for node '{}'", node.name));
      const std::vector<int> list = slots(entry.second, node, false);
      for (std::size_t i = 0; i < list.size(); ++i) {
        auto& role = node.roles[static_cast<std::size_t>(list[i])];
        if (role == CoordinateRole::fixed) {
          file_.fail(entry.second[i], fmt::format("coordinate '{}.{}' is both fixed (in 'supports') and independent", node.name,
                                                  framework::kSlotNames[static_cast<std::size_t>(list[i])]));
        }
        role = CoordinateRole::independent;
      }
    }
  }

  const YamlFile& file_;
  FrameworkModel model_;
  FrameworkNameIndex node_index_, element_index_;
  std::vector<TreeNode> orientations_;
  std::vector<TreeNode> element_nodes_;
  double length_ = 1.0;
};

}  // namespace

FrameworkModel read_framework_model(const YamlFile& file) { return FrameworkReader(file).read(); }

}  // namespace kinestat::io
