// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Shared by the readers of robot description formats (URDF, SDFormat, MJCF): a network model
// built joint by joint with the file position of every joint, so that problems the analysis
// finds later (a disconnected link, a degenerate joint) still point into the file.

#include <Eigen/Core>

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/loaded_network.hpp"
#include "kinestat/screw/coupling_basis.hpp"

namespace kinestat::io {

/// A network read from another program's file, with one line per thing that was read but
/// ignored (mimic joints, transmissions, actuators, ...).
struct ImportedNetwork {
  LoadedNetwork loaded;
  std::vector<std::string> notices;
};

/// What the readers of other programs' formats may read besides the file given.
struct ImportOptions {
  /// Read an included file (SDFormat <include><uri>, MJCF <include file=>) that lies outside the
  /// folder of the file given and its subfolders. Off by default: a model cannot make kinestat
  /// read files elsewhere (/etc, a home folder) unless the user allows it.
  bool allow_includes_outside_folder = false;
  /// How the model is placed in the world (URDF's root link, an SDFormat model without a joint to
  /// the world, a link or group of links that no joint connects to the rest).
  enum class Base {
    format_default,  ///< the base is the ground; a loose link or group floats (with a notice)
    fixed,           ///< the base is the ground; a loose link or group is welded to the ground
    floating,        ///< the base and every loose link or group float (a free coupling to the world)
  };
  Base base = Base::format_default;
  /// Largest model file read, in bytes (the command's --max-input-size), by every reader:
  /// kinestat YAML / JSON, bar tables, SPACAR, URDF, SDFormat and MJCF; 64 MiB by default
  /// (io::ReadingLimits::max_bytes).
  std::size_t max_input_bytes = std::size_t{64} << 20;
};

/// Deepest chain of includes read (a file that includes a file that includes ...).
inline constexpr int kMaxIncludeDepth = 16;

/// The canonical path of included file `target` (a file that exists), after checking that it
/// lies inside `folder` (the canonical folder of the model file given) unless `options` allow
/// files outside it. `written` is the include as written in the file, for the message; throws
/// InputError at `where` when the file is outside and not allowed.
std::string allowed_include(const std::string& target, const std::string& folder, const ImportOptions& options,
                            const SourceLocation& where, const std::string& written);

/// Geometry of one joint in the world frame (only what its type uses need be set).
struct JointGeometry {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector3d> axis, axis2, normal;
  double pitch = 0.0;  ///< helical pitch, length per radian
};

/// Builds a network model from bodies (links) and joints given with world-frame geometry.
class NetworkBuilder {
 public:
  /// `units` names the length unit of the file format ("m" for URDF and SDFormat), or "".
  NetworkBuilder(std::string path, std::string name, std::string units);

  /// Adds a body (a link) if it is not there yet; returns its index. Throws InputError (at the
  /// file) for an empty name or one that is not printable text.
  int body(const std::string& name);
  /// Makes `name` the ground (the world or root link).
  void set_ground(const std::string& name);
  /// Adds a coupling from body `from` to body `to` at `where`. Vectors are in the world frame;
  /// they are stored as decimals rounded to 1e-12 of the vector's largest component (so that
  /// models written with short decimals stay exact despite the pose arithmetic). Throws InputError at
  /// `where` for a duplicate name, a self-coupling or a degenerate geometry.
  void couple(const std::string& name, screw::CouplingType type, const std::string& from, const std::string& to,
              const JointGeometry& geometry, const SourceLocation& where);
  /// Lets the ground body `base` float: a new ground named "world" (or "world (ground)" when a link
  /// is named "world") is joined to `base` by a free coupling "<base> (floating base)" at the origin.
  void float_base(const std::string& base, const SourceLocation& where);
  /// Joins each group of bodies that no chain of couplings connects to the ground to the ground,
  /// at its first body in file order: a free coupling "<body> (floating)" or, when `grounded`, a
  /// rigid one "<body> (grounded)". Returns a notice naming them (empty when there were none).
  std::string mount_loose_groups(bool grounded);
  /// The finished model; throws InputError (at the file) when it has no couplings.
  LoadedNetwork finish();

 private:
  screw::Vec3 exact(const Eigen::Vector3d& v);
  std::string path_;
  LoadedNetwork loaded_;
  std::map<std::string, int> bodies_;
  std::unordered_set<std::string> coupling_names_;  ///< for the duplicate check, in constant time a joint
  int digits_ = 0;
};

}  // namespace kinestat::io
