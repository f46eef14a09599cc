// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The bar table (`.bars`, docs/formats.md "Bar tables"): a compact text form of a framework of
// pin-jointed bars for models of 10⁶–10⁷ bars, where the YAML form costs about 60 bytes and 7
// parsed nodes a bar. A header line, the dimension, then the nodes (one coordinate line each,
// named by their index), the bars (two node indices each) and the supports (a node index and
// the translations held):
//
//   kinestat bars 1
//   dimension 2
//   nodes 3
//   0 0
//   1 0
//   0 1
//   bars 3
//   0 1
//   1 2
//   2 0
//   supports 2
//   0 xy
//   1 y
//
// Blank lines and lines starting with '#' are skipped. Read in one pass over the text with no
// tree: about 20 bytes of file a bar in 2-D.

#include <string>
#include <string_view>

#include "kinestat/framework/framework_model.hpp"

namespace kinestat::io {

/// Whether `path` names a bar table (extension `.bars`, any case).
bool is_bar_table_path(const std::string& path);

/// The framework of bar table `text` read from `path` (named in messages): nodes "0", "1", ...
/// in file order, bars "1", "2", ... (rigid trusses), supports as fixed translations. Throws
/// InputError at the line and column of the first problem (a missing or malformed line, a count
/// that does not match, a node index out of range, a bar joining a node to itself or two
/// coincident nodes, a repeated support, anything after the supports). Memory is bounded by the
/// text: counts are checked against the lines that follow, never trusted for allocation.
framework::FrameworkModel parse_bar_table(const std::string& path, std::string_view text);

}  // namespace kinestat::io
