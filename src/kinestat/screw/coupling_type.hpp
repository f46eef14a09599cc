// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The kinds of coupling (joint) kinestat knows, with their file-format names.

#include <optional>
#include <string_view>
#include <vector>

namespace kinestat::screw {

enum class CouplingType {
  revolute,        ///< f = 1: rotation about `axis` through `point`
  prismatic,       ///< f = 1: translation along `axis`
  helical,         ///< f = 1: screw motion about `axis` through `point`, `pitch` (length per radian)
  cylindrical,     ///< f = 2: rotation about and translation along `axis`
  universal,       ///< f = 2: rotations about `axis` and `axis2` through `point`
  spherical,       ///< f = 3: rotations about x, y, z through `point`
  planar,          ///< f = 3 (ebene): rotation about `normal`, translations normal to it
  rigid,           ///< f = 0
  free,            ///< f = d
  point_on_plane,  ///< f = 5: sphere on plane, contact at `point`, plane `normal`
  point_on_line,   ///< planar higher pair (cam, pin in slot): rotation about `point`, slide normal to `normal`
  custom,          ///< explicit unit motion screws (and optionally actions)
};

/// Parses a file-format type name ("revolute", "point_on_plane", ...).
std::optional<CouplingType> parse_coupling_type(std::string_view name);
/// The file-format name of `type`.
std::string_view coupling_type_name(CouplingType type);
/// All type names, for error messages.
std::vector<std::string_view> coupling_type_names();
/// Geometry keys that `type` uses (besides `point`, which every type accepts).
std::vector<std::string_view> geometry_keys(CouplingType type);
/// Geometry keys that `type` requires.
std::vector<std::string_view> required_geometry_keys(CouplingType type);

}  // namespace kinestat::screw
