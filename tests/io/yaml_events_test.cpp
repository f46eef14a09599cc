// SPDX-License-Identifier: BSD-3-Clause
// The model reader parses YAML with libyaml's event parser (io/yaml_support.cpp). These tests
// pin what the reader adds to it or maps from it: positions (1-based, columns in characters),
// nulls, anchors defined again, aliases of undefined anchors, characters that YAML 1.1 takes as
// line ends or refuses, libyaml's syntax errors with the context they name, and JSON.
// Expected values are derived by hand from the texts (counting columns) and the YAML rules.

#include <gtest/gtest.h>

#include <string>

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace kinestat::io {
namespace {

std::string event_error_of(const std::string& text) {
  try {
    (void)YamlFile::parse("in.yaml", text);
    return "accepted";
  } catch (const InputError& error) {
    return error.what();
  }
}

bool starts(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

TEST(YamlEvents, MalformedYamlSaysWhereAndWhatWasBeingRead) {
  // The flow list opened by '[' at column 12 of line 2 never closes: the text ends at 3:1.
  const std::string message = event_error_of("kinestat: 1\ncouplings: [\n");
  EXPECT_TRUE(starts(message, "in.yaml:3:1: error: malformed YAML: ")) << message;
  EXPECT_NE(message.find("(in the flow list that starts at line 2, column 12)"), std::string::npos) << message;
  // libyaml's own context when it points elsewhere: the quoted string opened at 2:7 never ends.
  const std::string quote = event_error_of("kinestat: 1\nname: \"abc\n");
  EXPECT_TRUE(starts(quote, "in.yaml:3:1: error: malformed YAML: ")) << quote;
  EXPECT_NE(quote.find("that starts at line 2, column 7)"), std::string::npos) << quote;
  // A surrogate escape: libyaml's message, mapped to one that names the escape.
  EXPECT_NE(event_error_of("name: \"\\ud800\"\n").find("malformed YAML: invalid unicode escape"), std::string::npos);
}

TEST(YamlEvents, ColumnsCountCharactersNotBytes) {
  // "ä: [a, *u]": ä, ':', ' ', '[', 'a', ',', ' ' are 7 characters (8 bytes); '*' is column 8.
  EXPECT_TRUE(starts(event_error_of("\xC3\xA4: [a, *u]\n"), "in.yaml:1:8: error: the alias '*u' refers to an anchor that is "
                                                      "not defined before it ('&u')"))
      << event_error_of("\xC3\xA4: [a, *u]\n");
}

TEST(YamlEvents, PlainNullsEmptyNodesAndQuotedStrings) {
  // Untagged plain '~', 'null' and an empty value are nulls; quoted or tagged text is a string.
  const auto file = YamlFile::parse("in.yaml", "a: ~\nb: null\nc:\nd: ''\ne: !!str null\nf: \"null\"\ng: NULL\n");
  const TreeNode root = file.root();
  EXPECT_TRUE(root["a"].is_null());
  EXPECT_TRUE(root["b"].is_null());
  EXPECT_TRUE(root["c"].is_null());
  EXPECT_TRUE(root["g"].is_null());
  ASSERT_TRUE(root["d"].is_scalar());
  EXPECT_EQ(root["d"].scalar(), "");
  ASSERT_TRUE(root["e"].is_scalar());
  EXPECT_EQ(root["e"].scalar(), "null");
  ASSERT_TRUE(root["f"].is_scalar());
  EXPECT_EQ(root["f"].scalar(), "null");
  // Positions: key 'd' at 4:1, its value '' at 4:4; 'f' value at 6:4.
  EXPECT_EQ(root.key(3).line(), 4);
  EXPECT_EQ(root.key(3).column(), 1);
  EXPECT_EQ(root["d"].column(), 4);
  EXPECT_EQ(root["f"].line(), 6);
  EXPECT_EQ(root["f"].column(), 4);
}

TEST(YamlEvents, AnAnchorDefinedAgainServesTheAliasesAfterIt) {
  // YAML: an alias refers to the most recent node with its anchor.
  const auto file = YamlFile::parse("in.yaml", "a: &x [1]\nb: &x [1, 2, 3]\nc: *x\nd: [*x, *x]\n");
  EXPECT_EQ(file.root()["c"].size(), 3u);
  EXPECT_EQ(file.root()["d"][1].size(), 3u);
  // An alias before its anchor: 'a: *x' puts '*' at column 4.
  EXPECT_TRUE(starts(event_error_of("a: *x\nb: &x 1\n"), "in.yaml:1:4: error: the alias '*x' refers to an anchor that is not "
                                                   "defined before it"))
      << event_error_of("a: *x\nb: &x 1\n");
}

TEST(YamlEvents, CharactersYamlTakesAsLineEndsOrRefusesAreNamed) {
  // "kinestat: 1 # " is 14 characters: the C1 control in the comment is at column 15.
  EXPECT_TRUE(starts(event_error_of("kinestat: 1 # \xC2\x9B\n"), "in.yaml:1:15: error: control character U+009B is not allowed"))
      << event_error_of("kinestat: 1 # \xC2\x9B\n");
  // NEL (U+0085, a YAML 1.1 line end) after "name: a": column 8.
  EXPECT_TRUE(starts(event_error_of("name: a\xC2\x85" "b\n"), "in.yaml:1:8: error: control character U+0085 is not allowed"))
      << event_error_of("name: a\xC2\x85" "b\n");
  // The line and paragraph separators, raw: refused; as escapes in a double-quoted string: kept.
  EXPECT_TRUE(starts(event_error_of("name: a\xE2\x80\xA8" "b\n"), "in.yaml:1:8: error: the line separator U+2028 is not allowed"))
      << event_error_of("name: a\xE2\x80\xA8" "b\n");
  EXPECT_TRUE(starts(event_error_of("x: 1\nname: \xE2\x80\xA9\n"), "in.yaml:2:7: error: the line separator U+2029"))
      << event_error_of("x: 1\nname: \xE2\x80\xA9\n");
  const auto file = YamlFile::parse("in.yaml", "name: \"a\\u2028b\"\n");
  EXPECT_EQ(file.root()["name"].scalar(), "a\xE2\x80\xA8" "b");
  // The noncharacter U+FFFE after "name: ": column 7.
  EXPECT_TRUE(starts(event_error_of("name: \xEF\xBF\xBE\n"), "in.yaml:1:7: error: the noncharacter U+FFFE is not allowed"))
      << event_error_of("name: \xEF\xBF\xBE\n");
}

TEST(YamlEvents, CompactJsonReads) {
  // JSON without spaces after ':' and ',' (what JSON writers emit); positions as in YAML.
  const auto file = YamlFile::parse("in.json", "{\"kinestat\":1,\"name\":\"a\",\"x\":[1.5,-2e3,{\"k\":null}]}");
  const TreeNode root = file.root();
  ASSERT_EQ(root.size(), 3u);
  EXPECT_EQ(root["name"].scalar(), "a");
  ASSERT_EQ(root["x"].size(), 3u);
  EXPECT_EQ(root["x"][1].scalar(), "-2e3");
  EXPECT_TRUE(root["x"][2]["k"].is_null());
  // '{"kinestat":1,"name":"a","x":[' is 30 characters: the list's first item is at column 31.
  EXPECT_EQ(root["x"][0].column(), 31);
}

TEST(YamlEvents, OneDocumentEvenWithoutMarkers) {
  // After a document end marker, a second document starts at its '---' on line 3; without the
  // marker the text is not YAML 1.1 (a document after '...' must start with '---').
  EXPECT_TRUE(starts(event_error_of("kinestat: 1\n...\n---\nname: b\n"), "in.yaml:3:1: error: a second YAML document"))
      << event_error_of("kinestat: 1\n...\n---\nname: b\n");
  EXPECT_TRUE(starts(event_error_of("kinestat: 1\n...\nname: b\n"), "in.yaml:3:1: error: malformed YAML: "))
      << event_error_of("kinestat: 1\n...\nname: b\n");
  // Comments and blank lines only: no document.
  EXPECT_TRUE(starts(event_error_of("# nothing\n\n"), "in.yaml:1:1: error: empty model file")) << event_error_of("# nothing\n\n");
}

}  // namespace
}  // namespace kinestat::io
