// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/network_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "kinestat/io/model_vocabulary.hpp"
#include "kinestat/screw/coupling_basis.hpp"

namespace kinestat::io {

namespace {

using screw::CouplingType;
using screw::Rational;
using screw::Vec3;

class NetworkReader {
 public:
  explicit NetworkReader(const YamlFile& file) : file_(file) {}

  LoadedNetwork read() {
    const TreeNode& root = file_.root();
    file_.check_keys(root, "the model file",
                     {"kinestat", kSchemaKey, "kind", "name", "description", "dimension", "units", "ground", "bodies", "couplings", "chords",
                      "primary", "values", "inputs"});
    network::Model& model = loaded_.model;
    if (auto name = file_.optional(root, "name"); name.defined()) model.name = file_.string(name, "'name'");
    if (read_planar(file_, root, "network", false)) model.space = screw::ScrewSpace::planar();
    model.units = read_units(file_, root);
    if (auto bodies = file_.optional(root, "bodies"); bodies.defined()) read_bodies(bodies);
    const TreeNode couplings = file_.required(root, "couplings", "the model file");
    file_.expect_sequence(couplings, "'couplings'");
    if (couplings.size() == 0) file_.fail(couplings, "the model has no couplings: 'couplings' is empty");
    loaded_.field_locations["couplings"] = file_.where(couplings);
    // Room for every coupling at once: a Coupling's rationals make moving it a copy (GMP's move
    // constructor allocates), and growing the list copied each one twice on average (a 10^5
    // coupling ladder: 45 % of its reading).
    model.couplings.reserve(couplings.size());
    loaded_.item_locations["couplings"].reserve(couplings.size());
    coupling_names_.reserve(couplings.size());
    body_indices_.reserve(couplings.size());
    for (const auto& coupling : couplings.items()) read_coupling(coupling);
    order_bodies();
    if (auto ground = file_.optional(root, "ground"); ground.defined()) {
      const std::string name = body_name(ground, "'ground'");
      const auto it = std::find(model.bodies.begin(), model.bodies.end(), name);
      if (it == model.bodies.end()) file_.fail(ground, fmt::format("ground body '{}' is not a body of the model", name));
      model.ground = static_cast<int>(it - model.bodies.begin());
    }
    read_name_list(root, "chords", model.chords);
    read_name_list(root, "primary", model.primary);
    read_inputs(root);
    if (auto values = file_.optional(root, "values"); values.defined()) read_values(values);
    model.max_significant_digits = max_digits_;
    return std::move(loaded_);
  }

 private:
  std::string body_name(const TreeNode& node, std::string_view what) const {
    if (!node.is_scalar() || node.scalar().empty()) file_.fail(node, fmt::format("{} must be a body name or number", what));
    return std::string(node.scalar());
  }

  // Hashed, so reading e couplings costs O(e) rather than O(e · n).
  int body_index(const std::string& name) {
    auto& bodies = loaded_.model.bodies;
    const auto [it, inserted] = body_indices_.try_emplace(name, static_cast<int>(bodies.size()));
    if (inserted) bodies.push_back(name);
    return it->second;
  }

  void read_bodies(const TreeNode& bodies) {
    file_.expect_sequence(bodies, "'bodies'");
    std::set<std::string> seen;
    for (const auto& body : bodies.items()) {
      const std::string name = body_name(body, "a body");
      if (!seen.insert(name).second) file_.fail(body, fmt::format("duplicate body '{}'", name));
      body_index(name);
    }
  }

  // Bodies named by integers are numbered as the user numbered them; others keep the order
  // in which they first appear. Coupling ends are remapped accordingly.
  void order_bodies() {
    auto& model = loaded_.model;
    const bool all_integers = std::all_of(model.bodies.begin(), model.bodies.end(), [](const std::string& name) {
      return parse_exact_decimal(name).has_value() && parse_exact_decimal(name)->get_den() == 1 &&
             name.find_first_of(".eE") == std::string::npos;
    });
    if (!all_integers) return;
    std::vector<int> order(model.bodies.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      return *parse_exact_decimal(model.bodies[static_cast<std::size_t>(a)]) < *parse_exact_decimal(model.bodies[static_cast<std::size_t>(b)]);
    });
    std::vector<int> new_index(order.size());
    std::vector<std::string> sorted;
    for (std::size_t i = 0; i < order.size(); ++i) {
      new_index[static_cast<std::size_t>(order[i])] = static_cast<int>(i);
      sorted.push_back(model.bodies[static_cast<std::size_t>(order[i])]);
    }
    // "1" and "01" would both be body 1: a duplicate under another spelling.
    for (std::size_t i = 1; i < sorted.size(); ++i)
      if (*parse_exact_decimal(sorted[i]) == *parse_exact_decimal(sorted[i - 1]))
        file_.fail(file_.root(), fmt::format("bodies '{}' and '{}' are the same number", sorted[i - 1], sorted[i]));
    model.bodies = sorted;
    for (auto& c : model.couplings) {
      c.from = new_index[static_cast<std::size_t>(c.from)];
      c.to = new_index[static_cast<std::size_t>(c.to)];
    }
  }

  Rational number(const TreeNode& node, std::string_view what) {
    const ExactNumber n = file_.number(node, what);
    max_digits_ = std::max(max_digits_, significant_digits(node.scalar()));
    return *n.exact;
  }

  // A 3-vector; planar models also accept [x, y] and require z = 0 for points.
  Vec3 vector(const TreeNode& node, std::string_view what, bool nonzero, bool in_plane) {
    const bool planar = loaded_.model.space.is_planar();
    // Checks shape and finiteness and reads each number once.
    std::vector<ExactNumber> values = planar ? file_.numbers(node, what, {2, 3}) : file_.numbers(node, what, {3});
    Vec3 v{0, 0, 0};
    for (std::size_t i = 0; i < values.size(); ++i) {
      max_digits_ = std::max(max_digits_, significant_digits(node[i].scalar()));
      v[i] = std::move(*values[i].exact);
    }
    if (nonzero && screw::is_zero(v)) file_.fail(node, fmt::format("{} must not be the zero vector", what));
    if (planar && in_plane && sgn(v[2]) != 0) file_.fail(node, fmt::format("{} must lie in the xy-plane of a planar model", what));
    return v;
  }

  std::vector<std::vector<Rational>> screw_list(const TreeNode& node, std::string_view what) {
    file_.expect_sequence(node, what);
    const std::size_t d = static_cast<std::size_t>(loaded_.model.space.dimension());
    std::vector<std::vector<Rational>> screws;
    for (const auto& item : node.items()) {
      file_.numbers(item, what, {d});
      std::vector<Rational> s;
      for (const auto& x : item.items()) s.push_back(number(x, what));
      screws.push_back(s);
    }
    return screws;
  }

  // What read_coupling checks a coupling of one type against, built once per type.
  struct TypeKeys {
    std::string what;                     // "a revolute coupling", for messages
    std::vector<std::string> allowed;     // its keys
    std::vector<std::string_view> required;  // its required geometry keys
  };
  const TypeKeys& keys_of(CouplingType type) {
    auto [it, inserted] = type_keys_.try_emplace(type);
    if (inserted) {
      TypeKeys& keys = it->second;
      keys.what = fmt::format("a {} coupling", screw::coupling_type_name(type));
      keys.allowed = {"name", "type", "between", "point"};
      for (auto key : screw::geometry_keys(type)) keys.allowed.emplace_back(key);
      keys.required = screw::required_geometry_keys(type);
    }
    return it->second;
  }

  void read_coupling(const TreeNode& node) {
    file_.expect_map(node, "a coupling");
    const TreeNode type_node = file_.required(node, "type", "a coupling");
    const std::string type_name = file_.string(type_node, "'type'");
    const auto type = screw::parse_coupling_type(type_name);
    if (!type) {
      file_.fail(type_node, fmt::format("unknown coupling type '{}'; expected one of: {}", type_name,
                                        fmt::join(screw::coupling_type_names(), ", ")));
    }
    const TypeKeys& keys = keys_of(*type);
    file_.check_keys(node, keys.what, keys.allowed);
    for (auto key : keys.required) {
      if (key == "point" && !file_.optional(node, key).defined()) {
        const TreeNode name = file_.optional(node, "name");
        file_.fail(node, fmt::format("{} coupling{} needs a 'point' (on its axis, or its centre or contact point): its "
                                     "motions depend on where it is; write point: [0, 0, 0] if it is at the origin",
                                     type_name, name.is_scalar() ? fmt::format(" '{}'", name.scalar()) : ""));
      }
      file_.required(node, key, keys.what);
    }

    network::Coupling coupling;
    coupling.type = *type;
    const TreeNode name = file_.required(node, "name", "a coupling");
    coupling.name = file_.string(name, "a coupling name");
    if (!coupling_names_.insert(coupling.name).second)
      file_.fail(name, fmt::format("duplicate coupling name '{}'", coupling.name));

    const TreeNode between = file_.required(node, "between", "a coupling");
    file_.expect_sequence(between, "'between'");
    if (between.size() != 2) file_.fail(between, "'between' must name exactly two bodies, e.g. [1, 2]");
    const std::string from = body_name(between[0], "a body in 'between'");
    const std::string to = body_name(between[1], "a body in 'between'");
    if (from == to) file_.fail(between, fmt::format("coupling '{}' joins body '{}' to itself", coupling.name, from));
    coupling.from = body_index(from);
    coupling.to = body_index(to);

    screw::CouplingGeometry& g = coupling.geometry;
    if (auto point = file_.optional(node, "point"); point.defined()) g.point = vector(point, "'point'", false, true);
    if (auto axis = file_.optional(node, "axis"); axis.defined()) g.axis = vector(axis, "'axis'", true, false);
    if (auto axis2 = file_.optional(node, "axis2"); axis2.defined()) g.axis2 = vector(axis2, "'axis2'", true, false);
    if (auto normal = file_.optional(node, "normal"); normal.defined()) g.normal = vector(normal, "'normal'", true, false);
    if (auto pitch = file_.optional(node, "pitch"); pitch.defined()) g.pitch = number(pitch, "'pitch'");
    if (auto motions = file_.optional(node, "motions"); motions.defined()) g.custom_motions = screw_list(motions, "a custom motion");
    if (auto actions = file_.optional(node, "actions"); actions.defined()) g.custom_actions = screw_list(actions, "a custom action");

    const bool planar = loaded_.model.space.is_planar();
    // A planar model cannot have a coupling whose motions leave the plane: it is refused rather
    // than projected (a spherical joint would silently become a revolute).
    if (planar && (*type == CouplingType::spherical || *type == CouplingType::universal || *type == CouplingType::cylindrical ||
                   *type == CouplingType::helical || *type == CouplingType::point_on_plane || *type == CouplingType::planar))
      file_.fail(type_node, fmt::format("a planar model cannot have a {} coupling ('{}'); use revolute, prismatic, "
                                        "point_on_line, rigid, free or custom, or write 'dimension: spatial'",
                                        type_name, coupling.name));
    if (*type == CouplingType::revolute && !g.axis && !planar)
      file_.fail(node, fmt::format("revolute coupling '{}' needs an 'axis' in a spatial model", coupling.name));
    if (planar && *type == CouplingType::revolute && g.axis && (sgn((*g.axis)[0]) != 0 || sgn((*g.axis)[1]) != 0))
      file_.fail(file_.optional(node, "axis"), "in a planar model a revolute axis must be normal to the plane ([0, 0, 1])");
    if (planar && *type == CouplingType::prismatic && sgn((*g.axis)[2]) != 0)
      file_.fail(file_.optional(node, "axis"), "in a planar model a prismatic axis must lie in the xy-plane");
    try {
      // Refused here, where the coupling is written, exactly when the analysis's coupling_basis
      // would refuse it; the check builds no basis (with full-precision coordinates that takes
      // GMP, and the analysis builds it anyway).
      screw::check_coupling_geometry(coupling.type, g, loaded_.model.space);
    } catch (const screw::GeometryError& error) {
      file_.fail(node, fmt::format("coupling '{}': {}", coupling.name, error.what()));
    }
    loaded_.item_locations["couplings"].push_back(file_.where(node));
    loaded_.model.couplings.push_back(std::move(coupling));
  }

  void read_name_list(const TreeNode& root, const char* field, std::vector<std::string>& names) {
    const TreeNode list = file_.optional(root, field);
    if (!list.defined()) return;
    file_.expect_sequence(list, fmt::format("'{}'", field));
    loaded_.field_locations[field] = file_.where(list);
    std::set<std::string> seen;
    for (const auto& item : list.items()) {
      const std::string name = file_.string(item, fmt::format("an entry of '{}'", field));
      if (!seen.insert(name).second) file_.fail(item, fmt::format("'{}' appears twice in '{}'", name, field));
      names.push_back(name);
      loaded_.item_locations[field].push_back(file_.where(item));
    }
  }

  // Driven couplings: names of couplings, a name given twice for a pair driven twice.
  void read_inputs(const TreeNode& root) {
    const TreeNode list = file_.optional(root, "inputs");
    if (!list.defined()) return;
    file_.expect_sequence(list, "'inputs'");
    loaded_.field_locations["inputs"] = file_.where(list);
    for (const auto& item : list.items()) {
      const std::string name = file_.string(item, "an entry of 'inputs'");
      if (coupling_names_.count(name) == 0)
        file_.fail(item, fmt::format("'inputs' names '{}', which is not a coupling of the model", name));
      loaded_.model.inputs.push_back(name);
      loaded_.item_locations["inputs"].push_back(file_.where(item));
    }
  }

  void read_values(const TreeNode& values) {
    file_.expect_map(values, "'values'");
    loaded_.field_locations["values"] = file_.where(values);
    std::set<std::string> seen;
    for (const auto& entry : values.entries()) {
      const std::string name = file_.string(entry.first, "a primary variable name in 'values'");
      if (!seen.insert(name).second) file_.fail(entry.first, fmt::format("duplicate key '{}' in 'values'", name));
      loaded_.model.values.emplace_back(name, *file_.number(entry.second, fmt::format("the value of '{}'", name)).exact);
      loaded_.item_locations["values"].push_back(file_.where(entry.first));
    }
  }

  const YamlFile& file_;
  LoadedNetwork loaded_;
  std::unordered_map<std::string, int> body_indices_;  // body name -> index, while couplings are read
  std::unordered_set<std::string> coupling_names_;
  std::map<CouplingType, TypeKeys> type_keys_;
  int max_digits_ = 0;
};

}  // namespace

LoadedNetwork read_network_model(const YamlFile& file) { return NetworkReader(file).read(); }

InputError locate(const network::ModelError& error, const LoadedNetwork& loaded, const std::string& path) {
  SourceLocation where{path, 0, 0};
  if (auto field = loaded.field_locations.find(error.field()); field != loaded.field_locations.end()) where = field->second;
  if (auto items = loaded.item_locations.find(error.field());
      items != loaded.item_locations.end() && error.index() >= 0 &&
      static_cast<std::size_t>(error.index()) < items->second.size()) {
    where = items->second[static_cast<std::size_t>(error.index())];
  }
  if (where.line == 0) where = {path, 1, 1};
  return InputError(where, error.what());
}

}  // namespace kinestat::io
