// SPDX-License-Identifier: BSD-3-Clause
// Pictures checked by eye, and what a test can check of them (issue 10, item 5): in the
// mechanism drawing of every example (including the robot files and SPACAR decks) no two labels
// overlap and no label or line leaves the canvas, the verdict under the title is the text
// report's verdict, a network with a weld still draws, and the structural diagram names the
// bodies that are in no group.

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/cli_run.hpp"
#include "support/sanitizer_sample.hpp"

namespace {

using kinestat::testing::run_cli;

struct Label {
  std::string content, cls;
  double x0, y0, x1, y1;
};

// Inverse of the SVG writer's markup escaping, for the few entities it writes.
std::string unescape(std::string s) {
  for (const auto& [entity, plain] : std::vector<std::pair<std::string, std::string>>{{"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"}}) {
    for (std::size_t at = s.find(entity); at != std::string::npos; at = s.find(entity, at + plain.size())) s.replace(at, entity.size(), plain);
  }
  return s;
}

// Labels of the drawing area (node, element, coupling and screw names) with their boxes: an
// advance of 0.6 em a glyph (generous for Helvetica's digits and lower case) and the font's
// ascent and descent.
std::vector<Label> labels_of(const std::string& svg) {
  static const std::regex text_re("<text x=\"([-0-9.]+)\" y=\"([-0-9.]+)\" text-anchor=\"(\\w+)\" class=\"([-a-z]+)\" font-size=\"([0-9.]+)\"[^>]*>([^<]*)</text>");
  std::vector<Label> out;
  for (std::sregex_iterator it(svg.begin(), svg.end(), text_re), end; it != end; ++it) {
    const std::string cls = (*it)[4];
    if (cls != "node-label" && cls != "element-label" && cls != "coupling-label" && cls != "screw-label") continue;
    const std::string content = unescape((*it)[6]);
    std::size_t glyphs = 0;
    for (char c : content) glyphs += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    const double x = std::stod((*it)[1]), y = std::stod((*it)[2]), size = std::stod((*it)[5]);
    const double w = 0.6 * size * static_cast<double>(glyphs);
    const std::string anchor = (*it)[3];
    const double x0 = anchor == "middle" ? x - w / 2 : (anchor == "end" ? x - w : x);
    out.push_back({content, cls, x0, y - 0.8 * size, x0 + w, y + 0.25 * size});
  }
  return out;
}

double attribute(const std::string& svg, const std::string& name) {
  const std::regex re("<svg [^>]*" + name + "=\"([0-9.]+)\"");
  std::smatch m;
  return std::regex_search(svg, m, re) ? std::stod(m[1]) : 0.0;
}

std::vector<std::string> all_examples() {
  std::vector<std::string> files;
  const std::string root = std::string(KINESTAT_SOURCE_DIR) + "/examples";
  for (const char* folder : {"", "/robots", "/spacar"})
    for (const auto& entry : std::filesystem::directory_iterator(root + folder))
      if (entry.is_regular_file()) files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

bool is_structure_model(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("kind: structure", 0) == 0) return true;
  return false;
}

void expect_readable_labels(const std::string& svg) {
  const double width = attribute(svg, "width"), height = attribute(svg, "height");
  const auto labels = labels_of(svg);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const Label& a = labels[i];
    EXPECT_TRUE(a.x0 >= 0 && a.x1 <= width && a.y0 >= 0 && a.y1 <= height) << "'" << a.content << "' off the canvas";
    for (std::size_t j = i + 1; j < labels.size(); ++j) {
      const Label& b = labels[j];
      EXPECT_FALSE(a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1) << "'" << a.content << "' overlaps '" << b.content << "'";
    }
  }
  // Every line end on the canvas (screw axes, arrows, elements).
  static const std::regex line_re("<line [^>]*x1=\"([-0-9.]+)\" y1=\"([-0-9.]+)\" x2=\"([-0-9.]+)\" y2=\"([-0-9.]+)\"");
  for (std::sregex_iterator it(svg.begin(), svg.end(), line_re), end; it != end; ++it)
    for (int k : {1, 3}) {
      const double x = std::stod((*it)[k]), y = std::stod((*it)[k + 1]);
      EXPECT_TRUE(x >= 0 && x <= width && y >= 0 && y <= height) << "line end (" << x << ", " << y << ") off the canvas";
    }
}

void expect_verdict_of_text_report(const std::string& svg, const std::string& path) {
  const auto text = run_cli("analyze " + path);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  const std::string first = text.out.substr(0, text.out.find('\n'));
  ASSERT_EQ(first.rfind("Verdict: ", 0), 0U) << first;
  static const std::regex verdict_re("<text [^>]*class=\"verdict\"[^>]*>([^<]*)</text>");
  std::string joined;
  for (std::sregex_iterator it(svg.begin(), svg.end(), verdict_re), end; it != end; ++it)
    joined += (joined.empty() ? "" : " ") + unescape((*it)[1]);
  EXPECT_EQ(joined.substr(0, first.size()), first);
}

// Under AddressSanitizer a fixed quarter of the examples (support/sanitizer_sample.hpp).
TEST(MechanismPictures, LabelsApartOnTheCanvasAndTheVerdictOfTheTextReport) {
  int drawn = 0;
  for (const auto& path : kinestat::testing::sampled_under_sanitizer(all_examples())) {
    if (is_structure_model(path)) continue;  // no geometry to draw
    SCOPED_TRACE(path);
    const auto run = run_cli("draw --what mechanism " + path);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    ++drawn;
    expect_readable_labels(run.out);
    expect_verdict_of_text_report(run.out, path);
  }
  // Under the sanitizers about a quarter, give or take the structure models the stride lands on.
  EXPECT_GE(drawn, kinestat::kBuiltWithAddressSanitizer ? 39 / static_cast<int>(kinestat::testing::kSanitizerExampleStride) - 2 : 39);
}

TEST(MechanismPictures, NetworkWithAWeldStillDraws) {
  // A rigid coupling (MJCF weld) is no structural pair: only the structural diagram is refused.
  const std::string robot = std::string(KINESTAT_SOURCE_DIR) + "/examples/robots/four-bar.xml";
  EXPECT_EQ(run_cli("draw --what mechanism " + robot).exit_code, 0);
  EXPECT_EQ(run_cli("draw --what graph " + robot).exit_code, 0);
  const auto structure = run_cli("draw --what structure " + robot);
  EXPECT_EQ(structure.exit_code, 2);
  EXPECT_NE(structure.err.find("four-bar.xml:22:5: error: coupling 'D_weld' of type rigid"), std::string::npos) << structure.err;
}

TEST(StructuralDiagram, NamesTheBodiesInNoGroup) {
  // The Delta robot as a structure has no group at all (the structure report: 9 too many, every
  // body over-constrained): the diagram of the frame alone says so, naming every such body.
  const std::string model = std::string(KINESTAT_SOURCE_DIR) + "/examples/delta-robot.yaml";
  const auto json_run = run_cli("structure --json " + model);
  ASSERT_EQ(json_run.exit_code, 0) << json_run.err;
  const auto j = nlohmann::json::parse(json_run.out);
  const auto svg = run_cli("draw --what structure " + model);
  ASSERT_EQ(svg.exit_code, 0) << svg.err;
  static const std::regex note_re("<text class=\"left-out\"[^>]*>([^<]*)</text>");
  std::string notes;
  for (std::sregex_iterator it(svg.out.begin(), svg.out.end(), note_re), end; it != end; ++it) notes += unescape((*it)[1]) + " ";
  const auto& over = j["undecomposed"]["over_constrained"];
  ASSERT_FALSE(over.empty());
  EXPECT_NE(notes.find(fmt::format("over-constrained ({} constraint(s) or input(s) too many)", j["undecomposed"]["redundant"].get<int>())),
            std::string::npos)
      << notes;
  std::set<std::string> words;
  static const std::regex word_re("[^ ,:()]+");
  for (std::sregex_iterator it(notes.begin(), notes.end(), word_re), end; it != end; ++it) words.insert(it->str());
  for (const auto& body : over) {
    const std::string name = j["bodies"][body.get<std::size_t>() - 1];
    EXPECT_TRUE(words.count(name)) << name << " not named in: " << notes;
  }
  // A diagram with every body in a group has no such note.
  EXPECT_EQ(run_cli("draw --what structure " + std::string(KINESTAT_SOURCE_DIR) + "/examples/saura-eq2.yaml").out.find("left-out"),
            std::string::npos);
}

}  // namespace
