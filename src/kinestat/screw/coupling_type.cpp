#include "kinestat/screw/coupling_type.hpp"

#include <array>
#include <utility>

namespace kinestat::screw {

namespace {
constexpr std::array<std::pair<CouplingType, std::string_view>, 12> kNames{{
    {CouplingType::revolute, "revolute"},
    {CouplingType::prismatic, "prismatic"},
    {CouplingType::helical, "helical"},
    {CouplingType::cylindrical, "cylindrical"},
    {CouplingType::universal, "universal"},
    {CouplingType::spherical, "spherical"},
    {CouplingType::planar, "planar"},
    {CouplingType::rigid, "rigid"},
    {CouplingType::free, "free"},
    {CouplingType::point_on_plane, "point_on_plane"},
    {CouplingType::point_on_line, "point_on_line"},
    {CouplingType::custom, "custom"},
}};
}  // namespace

std::optional<CouplingType> parse_coupling_type(std::string_view name) {
  for (const auto& [type, text] : kNames)
    if (text == name) return type;
  return std::nullopt;
}

std::string_view coupling_type_name(CouplingType type) {
  for (const auto& [candidate, text] : kNames)
    if (candidate == type) return text;
  return "unknown";
}

std::vector<std::string_view> coupling_type_names() {
  std::vector<std::string_view> names;
  for (const auto& entry : kNames) names.push_back(entry.second);
  return names;
}

std::vector<std::string_view> geometry_keys(CouplingType type) {
  switch (type) {
    case CouplingType::revolute:
    case CouplingType::prismatic:
    case CouplingType::cylindrical: return {"axis"};
    case CouplingType::helical: return {"axis", "pitch"};
    case CouplingType::universal: return {"axis", "axis2"};
    case CouplingType::planar:
    case CouplingType::point_on_plane:
    case CouplingType::point_on_line: return {"normal"};
    case CouplingType::custom: return {"motions", "actions"};
    case CouplingType::spherical:
    case CouplingType::rigid:
    case CouplingType::free: return {};
  }
  return {};
}

std::vector<std::string_view> required_geometry_keys(CouplingType type) {
  switch (type) {
    case CouplingType::prismatic:
    case CouplingType::cylindrical: return {"axis"};
    case CouplingType::helical: return {"axis", "pitch"};
    case CouplingType::universal: return {"axis", "axis2"};
    case CouplingType::planar:
    case CouplingType::point_on_plane:
    case CouplingType::point_on_line: return {"normal"};
    case CouplingType::custom: return {"motions"};
    // A revolute's axis defaults to z, the only sensible axis in a planar model.
    case CouplingType::revolute:
    case CouplingType::spherical:
    case CouplingType::rigid:
    case CouplingType::free: return {};
  }
  return {};
}

}  // namespace kinestat::screw
