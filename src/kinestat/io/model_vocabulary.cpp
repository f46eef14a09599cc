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
  // Files of format version 1 wrote numbers before the words, each kind its own: a network its
  // screw dimension (6 spatial, 3 planar), a framework its coordinate dimension (3 spatial, 2
  // planar). Such a file is read as it was written, with a notice naming the word. A structure
  // file wrote `space:` instead (structure_reader.cpp), so numbers there are no old spelling.
  const bool network = kind == "network", framework = kind == "framework";
  if ((network && (text == "6" || text == "3")) || (framework && (text == "3" || text == "2"))) {
    const bool planar = text == (network ? "3" : "2");
    const char* word = planar ? "planar" : "spatial";
    file.notice(dimension, fmt::format("'dimension: {}' is the older spelling of 'dimension: {}' in a {} model (read as such); "
                                       "write 'dimension: {}'",
                                       text, word, kind, word));
    return planar;
  }
  // Otherwise a number is not guessed at: the old numbers meant different things in different
  // kinds (3 was planar for a network, spatial for a framework).
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
