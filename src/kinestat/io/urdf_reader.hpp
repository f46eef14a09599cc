// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reads a URDF robot description into a coupling network (docs/formats.md): links become
// bodies, joints couplings with their axes and positions resolved to the root link's frame;
// the root link (or `world`) is the ground. Closed loops: a joint whose child already has a
// parent (in file order) closes a loop, and so does Drake's <loop_joint>. Mimic joints and
// transmissions are noted and ignored. Errors are InputErrors at file:line:column.

#include <string>

#include "kinestat/io/network_import.hpp"

namespace kinestat::io {

/// True when this kinestat was built with tinyxml2 (needed for URDF and to recognise MJCF).
bool urdf_reader_built_in();

/// Reads URDF `text` that came from `path` (used in messages only). `options.base` says whether
/// the root link is the ground (the default) or floats, and how a loose link is mounted.
ImportedNetwork parse_urdf(const std::string& path, const std::string& text, const ImportOptions& options = {});

/// Reads the URDF file at `path`.
ImportedNetwork read_urdf(const std::string& path, const ImportOptions& options = {});

}  // namespace kinestat::io
