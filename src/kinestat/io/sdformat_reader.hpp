#pragma once
// Reads an SDFormat file (.sdf) through libsdformat into a coupling network (docs/formats.md):
// links become bodies, joints couplings with poses and axes resolved to the model frame; the
// world (when a joint attaches to it) or the canonical link is the ground. SDFormat allows
// closed loops (a link may be the child of several joints). Nested models are read with
// scoped names (outer::inner::link).

#include <string>

#include "kinestat/io/network_import.hpp"

namespace kinestat::io {

/// True when this kinestat was built with libsdformat.
bool sdformat_reader_built_in();

/// Reads the SDFormat file at `path`. Throws InputError at file:line:column for what
/// libsdformat rejects and for joints kinestat cannot express (gearbox).
ImportedNetwork read_sdformat(const std::string& path);

/// Reads SDFormat `text` that came from `path` (used in messages only).
ImportedNetwork parse_sdformat(const std::string& path, const std::string& text);

}  // namespace kinestat::io
