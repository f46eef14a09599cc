// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The merge step of a sharded sweep (docs/sweep.md): the lines of every shard's output, in
// variant order, checked to be one whole sweep.

#include <string>
#include <vector>

namespace kinestat::io {

/// The lines of the sweep output files at `paths` (each line a JSON object with `variant` and `of`,
/// as `kinestat sweep` writes them), sorted by `variant`, each line's bytes unchanged. Throws
/// InputError at file:line:column for a line that is not a sweep line, a variant that appears
/// twice, or an `of` that differs from the first line's; and, naming the first file, when
/// variants of 0 to of − 1 are missing (a shard's file not given, or a shard not finished).
/// Each file is read through the bounded reader of model files (at most 64 MiB, the limit on
/// YAML models, named in the error); empty files are allowed.
std::string merge_sweep_files(const std::vector<std::string>& paths);

}  // namespace kinestat::io
