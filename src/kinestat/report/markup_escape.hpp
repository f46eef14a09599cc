// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Text placed in SVG or HTML: the characters that markup would read as markup, escaped.

#include <string>

namespace kinestat::report {

/// `text` with &, <, > and " replaced by entities, and control characters (but tab and line
/// ends) and bytes that are not UTF-8 by U+FFFD: safe in element content and quoted attributes.
std::string markup_escape(const std::string& text);

}  // namespace kinestat::report
