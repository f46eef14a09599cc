// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Output files are written whole or not at all. A regular file (or a new one) is written to a
// uniquely named temporary file beside it and renamed over it, so a failure never leaves a
// partial report behind and parallel runs never collide. A device or FIFO (/dev/null, a pipe)
// is written directly, never replaced. Symbolic links are followed to their target.

#include <string>
#include <vector>

namespace kinestat::io {

/// Writes `content` to `path` as described above. Throws InputError naming `path` and the
/// reason (the system's error text) if it cannot; whatever it wrote to a regular file is removed.
void write_file_atomically(const std::string& path, const std::string& content);

/// Throws InputError (exit 2) naming `output` when it is the same existing regular file as one
/// of `inputs` (the same device and inode: symbolic and hard links are seen through), so that a
/// typo such as `convert model.dat model.dat` never replaces the user's model with an output.
/// Empty names, "-" (standard input or output), devices, FIFOs and files that do not exist yet
/// never match.
void refuse_output_over_inputs(const std::string& output, const std::vector<std::string>& inputs);

}  // namespace kinestat::io
