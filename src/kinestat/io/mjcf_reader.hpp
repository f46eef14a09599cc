// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reads a MuJoCo MJCF file through libmujoco into a coupling network (docs/formats.md): the
// body tree with its joints (hinge, slide, ball, free; several joints in one body become a
// chain), bodies without joints welded to their parent, and the <equality> constraints that
// close loops: connect (a spherical coupling at the anchor) and weld (rigid). The world body
// is the ground. Joint and tendon equalities are noted and ignored.

#include <string>

#include "kinestat/io/network_import.hpp"

namespace kinestat::io {

/// True when this kinestat was built with libmujoco.
bool mjcf_reader_built_in();

/// Reads the MJCF file at `path`. Each <include file=> is resolved as MuJoCo does, in the folder
/// of `path` (never the working directory), at most 16 deep and each file once; outside that
/// folder only when `options` allow it. Meshes, textures, heightfields, skins and materials are
/// never read: they are stripped before MuJoCo compiles the model (one notice says so). Errors
/// (MuJoCo's included) are InputErrors at file:line:column of the element, in the included file
/// where it is; a number that is not finite is refused where it is written.
ImportedNetwork read_mjcf(const std::string& path, const ImportOptions& options = {});

/// Reads MJCF `text` that came from `path` (used in messages only): without a folder, a text with
/// an <include> is refused.
ImportedNetwork parse_mjcf(const std::string& path, const std::string& text);

}  // namespace kinestat::io
