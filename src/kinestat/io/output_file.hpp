#pragma once
// Output files are written whole or not at all: a temporary file next to the target is
// renamed over it, so a failure never leaves a partial report behind.

#include <string>

namespace kinestat::io {

/// Writes `content` to `path` atomically. Throws InputError naming `path` if it cannot.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace kinestat::io
