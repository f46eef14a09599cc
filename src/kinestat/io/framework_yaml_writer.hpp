// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Writes a framework model as a kinestat model file (docs/framework.md), so that a model read
// from another format (SPACAR) can be seen, edited and analysed as YAML.

#include <string>
#include <vector>

#include "kinestat/framework/framework_model.hpp"

namespace kinestat::io {

/// The YAML text of `model`, preceded by `comments` (one `# ` line each). Reading it back with
/// read_framework_model gives the same nodes, elements, frames and roles.
std::string framework_yaml(const framework::FrameworkModel& model, const std::vector<std::string>& comments = {});

}  // namespace kinestat::io
