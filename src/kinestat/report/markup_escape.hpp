#pragma once
// Text placed in SVG or HTML: the characters that markup would read as markup, escaped.

#include <string>

namespace kinestat::report {

/// `text` with &, <, > and " replaced by entities, safe in element content and quoted attributes.
std::string markup_escape(const std::string& text);

}  // namespace kinestat::report
