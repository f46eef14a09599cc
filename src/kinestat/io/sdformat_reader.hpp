// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reads an SDFormat file (.sdf) through libsdformat into a coupling network (docs/formats.md):
// links become bodies, joints couplings with poses and axes resolved to the model frame; the
// world (when a joint attaches to it) or the canonical link is the ground. SDFormat allows
// closed loops (a link may be the child of several joints). Nested models are read with
// scoped names (outer::inner::link). Includes are resolved beside the including file.

#include <string>

#include "kinestat/io/network_import.hpp"

namespace kinestat::io {

/// True when this kinestat was built with libsdformat.
bool sdformat_reader_built_in();

/// Reads the SDFormat file at `path`. Each <include><uri> is resolved beside the file that holds
/// it (never in the working directory or system folders; `model://name` also in that folder's
/// parent), at most 16 includes deep, a file never inside itself, and outside the folder of `path`
/// only when `options` allow it. Throws InputError at file:line:column (naming the included file
/// where the problem is) for what libsdformat rejects in bodies, joints, frames and poses and for
/// joints kinestat cannot express (gearbox); libsdformat's errors in elements without kinematic
/// meaning (visuals, collisions, materials, surfaces, sensors, plugins) become notices.
ImportedNetwork read_sdformat(const std::string& path, const ImportOptions& options = {});

/// Reads SDFormat `text` that came from `path` (used in messages only): without a folder, a
/// text with an <include> is refused.
ImportedNetwork parse_sdformat(const std::string& path, const std::string& text);

}  // namespace kinestat::io
