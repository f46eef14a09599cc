// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Names and other user-supplied text placed in a text report, a DOT graph, a comment of a
// written file or an error message: every character that a terminal or a line-oriented reader
// would act on is written as a visible escape, so no name can break a document or a terminal.

#include <string>
#include <string_view>

namespace kinestat::io {

/// `text` with these written as escapes, everything else unchanged:
/// - C0 control characters (tab, line feed and carriage return included) and DEL: `\xHH`;
/// - C1 control characters U+0080-U+009F, the line and paragraph separators U+2028/U+2029 and
///   the bidirectional embedding, override and isolate controls U+202A-U+202E, U+2066-U+2069
///   (which reorder what a terminal shows): `\u{HHHH}`;
/// - bytes that are not part of well-formed UTF-8: `\xHH`.
/// A backslash stays as it is; the result is valid UTF-8 without control characters.
std::string printable_text(std::string_view text);

/// How many characters of the input a message may quote (io::input_excerpt).
inline constexpr std::size_t kExcerptCharacters = 40;

/// A short excerpt of input text for a message: its first line only, at most
/// kExcerptCharacters characters, escaped as printable_text does, with "…" where it was cut. A
/// message never carries more of a file than this, so naming the wrong file (a password file, a
/// private key) does not print it.
std::string input_excerpt(std::string_view text);

/// The length in bytes (1-4) of the well-formed UTF-8 character (RFC 3629: no overlong forms,
/// surrogates or code points above U+10FFFF) that starts at byte `i` of `text`, or 0 when the
/// bytes there are not one.
std::size_t utf8_character_length(std::string_view text, std::size_t i);

}  // namespace kinestat::io
