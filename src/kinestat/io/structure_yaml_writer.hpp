// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Writes a structure model (`kind: structure`, docs/structure.md) as a kinestat model file, so
// that `kinestat fix` can write the structure its verdict proposes.

#include <string>
#include <vector>

#include "kinestat/structure/structure_model.hpp"

namespace kinestat::io {

/// The YAML text of `model`, preceded by `comments` (one `# ` line each). Reading it back with
/// read_structure_model gives the same name, units, dimension, body names (the frame first),
/// and pairs in the same order with the same bodies, kinds, freedoms and inputs. A planar model
/// whose pairs are Table-1 codes in upper-triangle order is written as its adjacency matrix
/// (with `bodies:` when they are named other than 1, 2, ...); any other as `bodies:` and `pairs:`.
std::string structure_yaml(const structure::StructureModel& model, const std::vector<std::string>& comments = {});

}  // namespace kinestat::io
