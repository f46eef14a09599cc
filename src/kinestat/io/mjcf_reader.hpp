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

/// Reads the MJCF file at `path` (included files and assets resolved next to it).
ImportedNetwork read_mjcf(const std::string& path);

/// Reads MJCF `text` that came from `path` (used in messages only; no included files).
ImportedNetwork parse_mjcf(const std::string& path, const std::string& text);

}  // namespace kinestat::io
