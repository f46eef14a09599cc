// SPDX-License-Identifier: BSD-3-Clause
// Names with control characters in every text writer (issue 16): the readers refuse most of
// them, but the library's models can be built in code (as here, bypassing the readers) and a
// name may still hold a tab or a line feed. Every text report, the verdict block, the DOT graph
// and error messages print each name through io::printable_text, so no name reaches a terminal
// raw or breaks the layout. The expected escapes are written out by hand.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "kinestat/design/framework_verdict.hpp"
#include "kinestat/design/network_verdict.hpp"
#include "kinestat/design/structure_verdict.hpp"
#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/printable_text.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/report/framework_report.hpp"
#include "kinestat/report/markup_escape.hpp"
#include "kinestat/report/network_report.hpp"
#include "kinestat/report/structure_report.hpp"
#include "kinestat/report/verdict_report.hpp"
#include "kinestat/structure/decomposition.hpp"

namespace kinestat {
namespace {

using io::printable_text;
using namespace std::string_literals;

// ---- the helper --------------------------------------------------------------------------

TEST(PrintableText, EscapesAsciiControlCharactersAndDel) {
  EXPECT_EQ(printable_text("A\x1B[31m"), "A\\x1B[31m");
  EXPECT_EQ(printable_text("B\0x"s), "B\\x00x");
  EXPECT_EQ(printable_text("a\tb\nc\rd"), "a\\x09b\\x0Ac\\x0Dd");
  EXPECT_EQ(printable_text("\x07\x7F"), "\\x07\\x7F");
}

TEST(PrintableText, EscapesC1ControlsSeparatorsAndBidirectionalControls) {
  EXPECT_EQ(printable_text("x\xC2\x85y"), "x\\u{0085}y");        // NEL
  EXPECT_EQ(printable_text("\xC2\x9B" "31m"), "\\u{009B}31m");   // CSI
  EXPECT_EQ(printable_text("\xC2\x80"), "\\u{0080}");
  EXPECT_EQ(printable_text("\xE2\x80\xA8\xE2\x80\xA9"), "\\u{2028}\\u{2029}");
  EXPECT_EQ(printable_text("abc\xE2\x80\xAE" "fed"), "abc\\u{202E}fed");  // right-to-left override
  EXPECT_EQ(printable_text("\xE2\x80\xAA\xE2\x81\xA6\xE2\x81\xA9"), "\\u{202A}\\u{2066}\\u{2069}");
}

TEST(PrintableText, KeepsPrintableTextAndBackslashes) {
  EXPECT_EQ(printable_text("link 1 (crank)"), "link 1 (crank)");
  EXPECT_EQ(printable_text("a\\x1B"), "a\\x1B");
  EXPECT_EQ(printable_text("\xC3\xA9\xE6\x97\xA5\xF0\x9F\x98\x80"), "\xC3\xA9\xE6\x97\xA5\xF0\x9F\x98\x80");  // é 日 😀
  EXPECT_EQ(printable_text("\xC2\xA0\xC2\xBF"), "\xC2\xA0\xC2\xBF");  // U+00A0, U+00BF follow the C1 range
  EXPECT_EQ(printable_text("\xE2\x80\xA7\xE2\x80\xAF"), "\xE2\x80\xA7\xE2\x80\xAF");  // U+2027, U+202F: neighbours
  EXPECT_EQ(printable_text(""), "");
}

TEST(PrintableText, EscapesEachByteThatIsNotUtf8) {
  EXPECT_EQ(printable_text("\xFF"), "\\xFF");
  EXPECT_EQ(printable_text("a\x85" "b"), "a\\x85b");                // a lone continuation byte
  EXPECT_EQ(printable_text("\xC0\xAF"), "\\xC0\\xAF");              // overlong '/'
  EXPECT_EQ(printable_text("\xED\xA0\x80"), "\\xED\\xA0\\x80");     // a UTF-16 surrogate
  EXPECT_EQ(printable_text("\xE2\x82"), "\\xE2\\x82");              // cut short
  EXPECT_EQ(printable_text("\xF4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80");  // above U+10FFFF
}

TEST(PrintableText, Utf8CharacterLength) {
  EXPECT_EQ(io::utf8_character_length("a", 0), 1u);
  EXPECT_EQ(io::utf8_character_length("\xC3\xA9", 0), 2u);
  EXPECT_EQ(io::utf8_character_length("\xE6\x97\xA5", 0), 3u);
  EXPECT_EQ(io::utf8_character_length("\xF0\x9F\x98\x80", 0), 4u);
  EXPECT_EQ(io::utf8_character_length("x\xE6\x97\xA5", 1), 3u);
  EXPECT_EQ(io::utf8_character_length("\xE0\x80\x80", 0), 0u);  // overlong
  EXPECT_EQ(io::utf8_character_length("\xBF", 0), 0u);
}

TEST(PrintableText, MarkupEscapeReplacesBytesThatAreNotUtf8AndC1Controls) {
  EXPECT_EQ(report::markup_escape("a\xFF<b"), "a\xEF\xBF\xBD&lt;b");
  EXPECT_EQ(report::markup_escape("x\xC2\x9By"), "x\xEF\xBF\xBDy");
  EXPECT_EQ(report::markup_escape("\xC3\xA9\xC2\xA0"), "\xC3\xA9\xC2\xA0");
}

// ---- every text writer -------------------------------------------------------------------

// Hostile names and, by hand, how a text report must print them.
struct Name {
  std::string raw;
  std::string shown;
};
const Name kModel{"four\xC2\x85" "bar", "four\\u{0085}bar"};
const Name kUnits{"mm\t", "mm\\x09"};
const Name kGround{"ground\x1B[2J", "ground\\x1B[2J"};
const Name kLink{"link\r\nVerdict: exactly constrained", "link\\x0D\\x0AVerdict: exactly constrained"};
const Name kFirst{"A\x1B[31m", "A\\x1B[31m"};
const Name kSecond{"B\0x"s, "B\\x00x"};
const Name kThird{"C\xE2\x80\xAE" "d", "C\\u{202E}d"};

// True when `text` holds no control character but the line feeds the writer puts there, no C1
// control and nothing that is not UTF-8: what printable_text of it leaves alone, newlines apart.
bool terminal_safe(const std::string& text) {
  std::string without_newlines;
  for (char c : text) without_newlines += c == '\n' ? ' ' : c;
  return printable_text(without_newlines) == without_newlines;
}

// A planar body held by two revolutes at different points: locked (FN 0), one redundant
// constraint (C = 4 action freedoms, rank a = 3, CN = 1).
network::Model two_pin_link(bool hostile) {
  auto pick = [hostile](const Name& n) { return hostile ? n.raw : n.shown; };
  network::Model model;
  model.name = pick(kModel);
  model.units = pick(kUnits);
  model.space = screw::ScrewSpace::planar();
  model.bodies = {pick(kGround), pick(kLink)};
  network::Coupling a{pick(kFirst), screw::CouplingType::revolute, 0, 1, {}};
  network::Coupling b{pick(kSecond), screw::CouplingType::revolute, 0, 1, {}};
  b.geometry.point = {1, 0, 0};
  model.couplings = {a, b};
  return model;
}

TEST(PrintableTextInReports, NetworkTextAndVerdictPrintEveryNameEscaped) {
  std::string text[2];
  for (bool hostile : {true, false}) {
    const auto model = two_pin_link(hostile);
    const auto result = network::analyse_network(model);
    ASSERT_EQ(result.FN, 0);
    ASSERT_EQ(result.CN, 1);
    const auto verdict = design::network_verdict(model, result);
    text[hostile ? 0 : 1] = report::network_report_text(model, result, {true, &verdict});
  }
  // The hostile names print exactly as the names that are their escapes, character for character.
  EXPECT_EQ(text[0], text[1]);
  EXPECT_TRUE(terminal_safe(text[0])) << text[0];
  for (const Name* n : {&kModel, &kUnits, &kGround, &kLink, &kFirst, &kSecond})
    EXPECT_NE(text[0].find(n->shown), std::string::npos) << n->shown;
  // The verdict names the redundant couplings, escaped.
  const auto verdict_end = text[0].find("\n\n");
  ASSERT_NE(verdict_end, std::string::npos);
  EXPECT_NE(text[0].substr(0, verdict_end).find(kFirst.shown), std::string::npos) << text[0];
}

TEST(PrintableTextInReports, SparseNetworkTextPrintsNamesEscaped) {
  const auto model = two_pin_link(true);
  network::SparseNetworkResult result;
  result.d = 3;
  result.stressed = {0, 1};
  result.moving = {};
  const std::string text = report::sparse_network_report_text(model, result);
  EXPECT_TRUE(terminal_safe(text)) << text;
  EXPECT_NE(text.find(kModel.shown + "\n"), std::string::npos);
  EXPECT_NE(text.find(kFirst.shown + ", " + kSecond.shown), std::string::npos) << text;
}

// A planar triangle n1 n2 n3 with n1, n2 fixed and the bar n1-n3 doubled: one self-stress in
// the two bars n1-n3 (equal and opposite), no mechanism.
framework::FrameworkModel doubled_bar(bool hostile) {
  auto pick = [hostile](const Name& n) { return hostile ? n.raw : n.shown; };
  using framework::CoordinateRole;
  framework::FrameworkModel model;
  model.name = pick(kModel);
  model.units = pick(kUnits);
  model.dimension = 2;
  auto node = [](std::string name, double x, double y, bool fixed) {
    framework::Node n;
    n.name = std::move(name);
    n.position = {x, y, 0};
    if (fixed) n.roles[0] = n.roles[1] = CoordinateRole::fixed;
    return n;
  };
  model.nodes = {node(pick(kGround), 0, 0, true), node("n2", 1, 0, true), node(pick(kLink), 0.5, 1, false)};
  auto truss = [](std::string name, std::size_t p, std::size_t q) {
    framework::Element e;
    e.name = std::move(name);
    e.nodes = {p, q};
    e.roles = {framework::DeformationRole::fixed};
    return e;
  };
  model.elements = {truss(pick(kFirst), 0, 2), truss("e2", 1, 2), truss(pick(kThird), 0, 2)};
  return model;
}

TEST(PrintableTextInReports, FrameworkTextAndVerdictPrintEveryNameEscaped) {
  std::string text[2];
  for (bool hostile : {true, false}) {
    const auto model = doubled_bar(hostile);
    const auto analysis = framework::analyse_framework(model);
    ASSERT_EQ(analysis.mechanisms, 0);
    ASSERT_EQ(analysis.self_stresses, 1);
    const auto verdict = design::framework_verdict(model, analysis);
    text[hostile ? 0 : 1] = report::framework_report_text(model, analysis, &verdict);
  }
  EXPECT_EQ(text[0], text[1]);
  EXPECT_TRUE(terminal_safe(text[0])) << text[0];
  for (const Name* n : {&kModel, &kUnits, &kFirst, &kThird})
    EXPECT_NE(text[0].find(n->shown), std::string::npos) << n->shown << "\n" << text[0];
  EXPECT_NE(text[0].find(kFirst.shown + ".elongation"), std::string::npos) << text[0];
}

// A planar four-bar, bodies frame, crank, coupler, rocker, driven at the crank: one group of
// two bodies after the crank's group.
structure::StructureModel four_bar(bool hostile) {
  auto pick = [hostile](const Name& n) { return hostile ? n.raw : n.shown; };
  structure::StructureModel model;
  model.name = pick(kModel);
  model.units = pick(kUnits);
  model.body_names = {pick(kGround), pick(kLink), pick(kFirst), pick(kThird)};
  model.pairs = {{0, 1, structure::PairKind::lower, 1, 1},
                 {1, 2, structure::PairKind::lower, 1, 0},
                 {2, 3, structure::PairKind::lower, 1, 0},
                 {3, 0, structure::PairKind::lower, 1, 0}};
  return model;
}

TEST(PrintableTextInReports, StructureTextAndVerdictPrintEveryNameEscaped) {
  std::string text[2];
  for (bool hostile : {true, false}) {
    const auto model = four_bar(hostile);
    const auto decomposition = structure::analyse_structure(model);
    ASSERT_TRUE(decomposition.complete());
    const auto verdict = design::structure_verdict(model, decomposition);
    text[hostile ? 0 : 1] = report::structure_report_text({model, decomposition, nullptr, structure::SearchMethod::matching,
                                                    &verdict, model.units});
  }
  EXPECT_EQ(text[0], text[1]);
  EXPECT_TRUE(terminal_safe(text[0])) << text[0];
  for (const Name* n : {&kModel, &kUnits, &kLink, &kFirst, &kThird})
    EXPECT_NE(text[0].find(n->shown), std::string::npos) << n->shown << "\n" << text[0];
}

TEST(PrintableTextInReports, DotLabelEscapesControlsThenQuotes) {
  auto model = four_bar(true);
  model.name = "a\"b\\c\x1B\n";
  const std::string dot = report::structure_dot(model, structure::analyse_structure(model));
  // printable_text gives  a"b\c\x1B\x0A ; DOT quoting then doubles each backslash and escapes ".
  EXPECT_NE(dot.find("  label=\"a\\\"b\\\\c\\\\x1B\\\\x0A\";\n"), std::string::npos) << dot;
  EXPECT_TRUE(terminal_safe(dot));
}

TEST(PrintableTextInReports, VerdictTextEscapesEveryString) {
  design::Verdict v;
  v.summary = "s\x1B.";
  v.states = {{"mode", "d\r", {{"coupling", "n\0"s, 1.0, "t\xC2\x9B"}}}};
  v.changes = {{"replace", "coupling", "x\x07", "free\x1B", "r\x7F", "rev\n", {}}};
  v.becomes = "b\x08";
  v.note = "n\xE2\x80\xAE";
  const std::string text = report::verdict_text(v);
  EXPECT_TRUE(terminal_safe(text)) << text;
  for (const char* shown : {"s\\x1B.", "d\\x0D", "n\\x00", "t\\u{009B}", "x\\x07", "rev\\x0A", "free\\x1B", "r\\x7F",
                            "b\\x08", "n\\u{202E}"})
    EXPECT_NE(text.find(shown), std::string::npos) << shown << "\n" << text;
}

TEST(PrintableTextInReports, InputErrorsShowControlCharactersEscaped) {
  const io::InputError error({"m\x1B.yaml", 3, 4}, "no magnitude named 'a\x1B[2Jb\xC2\x85'");
  EXPECT_STREQ(error.what(), "m\\x1B.yaml:3:4: error: no magnitude named 'a\\x1B[2Jb\\u{0085}'");
}

}  // namespace
}  // namespace kinestat
