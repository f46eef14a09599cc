// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The HTML viewer's assets, embedded at build time (cmake/KinestatViewer.cmake): three.js
// from the npm registry and kinestat's viewer.js / viewer.css.

#include <string>

namespace kinestat::report::viewer_assets {

/// False when three.js could not be installed at build time (no npm): no HTML reports.
bool built_in();
std::string three_js();
std::string viewer_js();
std::string viewer_css();

}  // namespace kinestat::report::viewer_assets
