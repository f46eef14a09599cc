// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/design/framework_change_application.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "kinestat/error.hpp"

namespace kinestat::design {

namespace {

using framework::CoordinateRole;
using framework::DeformationRole;
using framework::Element;
using framework::ElementType;
using framework::FrameworkModel;

[[noreturn]] void refuse(const DesignChange& change, const std::string& why) {
  throw Error(fmt::format("change '{} {} {}': {}", change.action, change.target_kind, change.target, why));
}

std::optional<std::size_t> node_index(const FrameworkModel& model, const std::string& name) {
  for (std::size_t i = 0; i < model.nodes.size(); ++i)
    if (model.nodes[i].name == name) return i;
  return std::nullopt;
}

std::optional<std::size_t> element_index(const FrameworkModel& model, const std::string& name) {
  for (std::size_t e = 0; e < model.elements.size(); ++e)
    if (model.elements[e].name == name) return e;
  return std::nullopt;
}

// "B–F" split at the separator where both halves are node names (a name may hold the separator).
std::pair<std::size_t, std::size_t> bar_nodes(const FrameworkModel& model, const DesignChange& change) {
  const std::string separator = kBarNodeSeparator;
  for (std::size_t at = change.target.find(separator); at != std::string::npos;
       at = change.target.find(separator, at + 1)) {
    const auto p = node_index(model, change.target.substr(0, at));
    const auto q = node_index(model, change.target.substr(at + separator.size()));
    if (p && q) {
      if (*p == *q) refuse(change, "a bar needs two different nodes");
      return {*p, *q};
    }
  }
  refuse(change, "expected two node names of the model joined by '–'");
}

// "<node>.<slot>": the node's index and slot, the slot one the node has.
std::pair<std::size_t, int> coordinate(const FrameworkModel& model, const DesignChange& change) {
  const std::size_t dot = change.target.rfind('.');
  if (dot != std::string::npos) {
    if (const auto node = node_index(model, change.target.substr(0, dot))) {
      const std::string slot_name = change.target.substr(dot + 1);
      for (int slot : framework::node_slots(model.dimension, model.nodes[*node]))
        if (slot_name == framework::kSlotNames[static_cast<std::size_t>(slot)]) return {*node, slot};
    }
  }
  refuse(change, "expected a coordinate '<node>.<x|y|z|rx|ry|rz>' the node has");
}

// "<element>.<deformation>": element names and deformation names may both hold dots.
std::pair<std::size_t, std::size_t> deformation(const FrameworkModel& model, const DesignChange& change) {
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const std::string& name = model.elements[e].name;
    if (change.target.size() <= name.size() + 1 || change.target.compare(0, name.size(), name) != 0 ||
        change.target[name.size()] != '.')
      continue;
    const std::string rest = change.target.substr(name.size() + 1);
    const auto names = framework::deformation_names(model, model.elements[e]);
    const auto found = std::find(names.begin(), names.end(), rest);
    if (found != names.end()) return {e, static_cast<std::size_t>(found - names.begin())};
  }
  refuse(change, "expected '<element>.<deformation>' of the model");
}

std::string unused_element_name(const FrameworkModel& model, const std::string& wanted) {
  std::string name = wanted;
  for (int k = 2; element_index(model, name); ++k) name = fmt::format("{}.{}", wanted, k);
  return name;
}

void apply(FrameworkModel& model, const DesignChange& change) {
  if (change.action == "add" && change.target_kind == "bar") {
    const auto [p, q] = bar_nodes(model, change);
    Element bar;
    bar.name = unused_element_name(model, change.target);
    bar.type = ElementType::truss;
    bar.nodes = {p, q};
    bar.roles.assign(framework::deformation_count(model.dimension, bar), DeformationRole::fixed);
    model.elements.push_back(std::move(bar));
    return;
  }
  if (change.action == "support" && change.target_kind == "coordinate") {
    const auto [node, slot] = coordinate(model, change);
    CoordinateRole role = CoordinateRole::fixed;
    if (change.becomes == "independent") role = CoordinateRole::independent;
    else if (change.becomes == "dependent") role = CoordinateRole::dependent;
    else if (change.becomes != "fixed") refuse(change, "a coordinate becomes 'fixed', 'independent' or 'dependent'");
    model.nodes[node].roles[static_cast<std::size_t>(slot)] = role;
    return;
  }
  if (change.action == "remove" && change.target_kind == "bar") {
    const auto e = element_index(model, change.target);
    if (!e) refuse(change, "no element of that name");
    model.elements.erase(model.elements.begin() + static_cast<std::ptrdiff_t>(*e));
    return;
  }
  if (change.action == "release" && (change.target_kind == "deformation" || change.target_kind == "rigid body")) {
    const auto [e, d] = deformation(model, change);
    DeformationRole role = DeformationRole::released;
    if (change.becomes == "fixed") role = DeformationRole::fixed;
    else if (change.becomes != "released") refuse(change, "a deformation becomes 'released' or 'fixed'");
    model.elements[e].roles[d] = role;
    return;
  }
  refuse(change, "not a framework change (add bar, support coordinate, remove bar, release deformation)");
}

}  // namespace

FrameworkModel apply_framework_change_set(const FrameworkModel& model, const std::vector<DesignChange>& changes) {
  FrameworkModel changed = model;
  for (const DesignChange& change : changes) apply(changed, change);
  return changed;
}

}  // namespace kinestat::design
