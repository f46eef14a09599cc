// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A design sweep run (docs/sweep.md): every variant of one shard of a spec, in ascending order,
// read and analysed as `kinestat analyze --json` would, each turned into its line. The command
// and the Python module both run sweeps through this (the pipeline analyses each variant).

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "kinestat/design/sweep_grid.hpp"
#include "kinestat/io/sweep_spec.hpp"

namespace kinestat::pipeline {

struct SweepRunOptions {
  design::SweepShard shard;          ///< the variants v with v mod shard.count == shard.index
  std::optional<double> tolerance;   ///< relative rank tolerance, as `analyze --tolerance`
  bool full = false;                 ///< whole reports in the lines, not the selection
};

/// Runs the variants of `options.shard` of `spec` in ascending order and hands each line (one
/// line of JSON with its newline) to `on_line`. Reads the spec's model (or each variant file)
/// relative to the spec's folder. A bad or unreadable model, or a parameter that addresses no
/// plain number of it, is an InputError before any line; a variant that cannot be analysed
/// gives an `error` line. Returns how many variants gave an error line.
std::uint64_t run_sweep(const io::SweepSpec& spec, const SweepRunOptions& options,
                        const std::function<void(const std::string& line)>& on_line);

}  // namespace kinestat::pipeline
