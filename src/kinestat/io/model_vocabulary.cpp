// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/model_vocabulary.hpp"

#include <fmt/format.h>

namespace kinestat::io {

bool read_planar(const YamlFile& file, const TreeNode& root, std::string_view kind, bool planar_default) {
  const TreeNode dimension = file.optional(root, "dimension");
  if (!dimension.defined()) return planar_default;
  const std::string text(dimension.is_scalar() ? dimension.scalar() : "");
  if (text == "spatial") return false;
  if (text == "planar") return true;
  // The old numbers meant different things in different kinds (3 was planar for a network,
  // spatial for a framework), so none is guessed at.
  if (text == "6")
    file.fail(dimension, "'dimension' takes a word: write 'dimension: spatial' (motion in space, d = 6)");
  if (text == "2")
    file.fail(dimension, "'dimension' takes a word: write 'dimension: planar' (motion in the xy-plane, d = 3)");
  if (text == "3")
    file.fail(dimension, fmt::format("'dimension: 3' is ambiguous in a {} model: write 'dimension: planar' for motion in the "
                                     "xy-plane (screw dimension d = 3) or 'dimension: spatial' for motion in space (d = 6)",
                                     kind));
  file.fail(dimension, "'dimension' must be 'spatial' or 'planar'");
}

std::string read_units(const YamlFile& file, const TreeNode& root) {
  const TreeNode units = file.optional(root, "units");
  if (!units.defined()) return "";
  return file.string(units, "'units' (the name of the length unit, e.g. mm)");
}

}  // namespace kinestat::io
