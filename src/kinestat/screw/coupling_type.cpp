// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/screw/coupling_type.hpp"

#include <array>

namespace kinestat::screw {

namespace {

// One row per type: file-format name, geometry keys it uses, and which of them are required.
// `point` (allowed for every type) is required wherever the screws depend on it: a forgotten
// point would silently put the joint at the origin and change the answer.
// A revolute's axis is optional: it defaults to z, the only axis a planar model allows
// (the network reader requires it in spatial models).
struct TypeFacts {
  CouplingType type;
  std::string_view name;
  std::vector<std::string_view> keys;
  std::vector<std::string_view> required;
};

const std::array<TypeFacts, 12>& type_facts() {
  static const std::array<TypeFacts, 12> facts{{
      {CouplingType::revolute, "revolute", {"axis"}, {"point"}},
      {CouplingType::prismatic, "prismatic", {"axis"}, {"axis"}},
      {CouplingType::helical, "helical", {"axis", "pitch"}, {"axis", "pitch", "point"}},
      {CouplingType::cylindrical, "cylindrical", {"axis"}, {"axis", "point"}},
      {CouplingType::universal, "universal", {"axis", "axis2"}, {"axis", "axis2", "point"}},
      {CouplingType::spherical, "spherical", {}, {"point"}},
      {CouplingType::planar, "planar", {"normal"}, {"normal", "point"}},
      {CouplingType::rigid, "rigid", {}, {}},
      {CouplingType::free, "free", {}, {}},
      {CouplingType::point_on_plane, "point_on_plane", {"normal"}, {"normal", "point"}},
      {CouplingType::point_on_line, "point_on_line", {"normal"}, {"normal", "point"}},
      {CouplingType::custom, "custom", {"motions", "actions"}, {"motions"}},
  }};
  return facts;
}

const TypeFacts& facts_of(CouplingType type) {
  for (const auto& facts : type_facts())
    if (facts.type == type) return facts;
  return type_facts().front();  // unreachable: every enumerator has a row
}

}  // namespace

std::optional<CouplingType> parse_coupling_type(std::string_view name) {
  for (const auto& facts : type_facts())
    if (facts.name == name) return facts.type;
  return std::nullopt;
}

std::string_view coupling_type_name(CouplingType type) { return facts_of(type).name; }

std::vector<std::string_view> coupling_type_names() {
  std::vector<std::string_view> names;
  for (const auto& facts : type_facts()) names.push_back(facts.name);
  return names;
}

std::vector<std::string_view> geometry_keys(CouplingType type) { return facts_of(type).keys; }

std::vector<std::string_view> required_geometry_keys(CouplingType type) { return facts_of(type).required; }

}  // namespace kinestat::screw
