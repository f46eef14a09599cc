// SPDX-License-Identifier: BSD-3-Clause
// Reading structure models: the matrix form, the named-pairs form, the bare stdin matrix,
// and one clear error (file:line:column, row and column) for each kind of bad input.
#include <gtest/gtest.h>

#include "kinestat/io/structure_reader.hpp"

namespace kinestat::io {
namespace {

structure::StructureModel parse(const std::string& text) {
  return read_structure_model(YamlFile::parse("model.yaml", text));
}

std::string error_of(const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

TEST(StructureReader, MatrixFormBuildsTable1Pairs) {
  const auto model = parse(
      "kinestat: 1\nkind: structure\nadjacency:\n  - [0, 4, 1]\n  - [4, 0, 5]\n  - [1, 5, 0]\n");
  ASSERT_EQ(model.body_count(), 3);
  ASSERT_EQ(model.pairs.size(), 3u);
  // Upper triangle, row by row: (1 2) code 4, (1 3) code 1, (2 3) code 5.
  EXPECT_EQ(model.pairs[0].kind, structure::PairKind::higher);
  EXPECT_EQ(model.pairs[0].inputs, 1);
  EXPECT_EQ(model.pairs[0].freedoms, 2);
  EXPECT_EQ(model.pairs[1].kind, structure::PairKind::lower);
  EXPECT_EQ(model.pairs[1].freedoms, 1);
  EXPECT_EQ(model.pairs[2].inputs, 2);
  EXPECT_EQ(structure::adjacency_of(model), (std::vector<std::vector<int>>{{0, 4, 1}, {4, 0, 5}, {1, 5, 0}}));
}

TEST(StructureReader, NamedPairsMatchTheMatrix) {
  const auto named = parse(
      "kinestat: 1\nkind: structure\nbodies: [ground, crank, coupler, rocker]\npairs:\n"
      "  - {between: [ground, crank], pair: lower, inputs: 1}\n"
      "  - {between: [crank, coupler], pair: lower}\n"
      "  - {between: [rocker, coupler], pair: lower}\n"
      "  - {between: [rocker, ground], pair: higher}\n");
  EXPECT_EQ(structure::adjacency_of(named),
            (std::vector<std::vector<int>>{{0, 3, 0, 2}, {3, 0, 1, 0}, {0, 1, 0, 1}, {2, 0, 1, 0}}));
  EXPECT_EQ(named.body_names[3], "rocker");
}

TEST(StructureReader, StdinMatrixWithCommentsAndCommas) {
  const auto model = read_adjacency_text("# four-bar\n0 3 0 1\n3 0 1 0\n\n0,1,0,1\n1 0 1 0  # last row\n");
  EXPECT_EQ(model.body_count(), 4);
  EXPECT_EQ(model.input_count(), 1);
}

TEST(StructureReader, NonSymmetricNamesRowAndColumn) {
  const std::string message = error_of([] { read_adjacency_text("0 1 0\n1 0 1\n0 0 0\n", "<stdin>"); });
  EXPECT_EQ(message, "<stdin>:3:3: error: adjacency is not symmetric: row 2, column 3 is 1 but row 3, column 2 is 0");
}

TEST(StructureReader, CodeOutsideTable1) {
  const std::string message = error_of([] {
    parse("kinestat: 1\nkind: structure\nadjacency:\n  - [0, 7]\n  - [7, 0]\n");
  });
  EXPECT_NE(message.find("model.yaml:4:9: error: adjacency code at row 1, column 2 is 7; expected 0 to 5"), std::string::npos)
      << message;
}

TEST(StructureReader, FrameWithoutPairs) {
  const std::string message = error_of([] { read_adjacency_text("0 0 0\n0 0 1\n0 1 0\n", "m.txt"); });
  EXPECT_EQ(message, "m.txt:1:1: error: the frame (row 1) forms no pair: nothing is attached to it");
}

TEST(StructureReader, IsolatedBody) {
  const std::string message = error_of([] { read_adjacency_text("0 1 0\n1 0 0\n0 0 0\n", "m.txt"); });
  EXPECT_EQ(message, "m.txt:3:1: error: body 3 is isolated: row 3 forms no pair");
}

TEST(StructureReader, IsolatedNamedBody) {
  const std::string message = error_of([] {
    parse("kinestat: 1\nkind: structure\nbodies: [frame, a, b]\npairs:\n  - {between: [frame, a], pair: lower, inputs: 1}\n");
  });
  EXPECT_EQ(message, "model.yaml:3:20: error: body 'b' (body 3) is isolated: it forms no pair");
}

TEST(StructureReader, OtherMistakes) {
  EXPECT_NE(error_of([] { read_adjacency_text("0 1\n1 0 0\n"); }).find("must be square: row 2 has 3 entries"),
            std::string::npos);
  EXPECT_NE(error_of([] { read_adjacency_text("0 x\n1 0\n"); }).find("<stdin>:1:3: error: adjacency row 1, column 2 must be an integer"),
            std::string::npos);
  EXPECT_NE(error_of([] { read_adjacency_text("1 1\n1 0\n"); }).find("diagonal must be 0: row 1, column 1 is 1"),
            std::string::npos);
  EXPECT_NE(error_of([] { parse("kinestat: 1\nkind: structure\nbodies: [f, a]\npairs:\n  - {between: [f, z], pair: lower}\n"); })
                .find("model.yaml:5:19: error: unknown body 'z'"),
            std::string::npos);
  EXPECT_NE(error_of([] { parse("kinestat: 1\nkind: structure\nbodies: [f, a]\npairs:\n  - {between: [f, a], pair: lower, inputs: 2}\n"); })
                .find("'inputs' must be 0 to 1"),
            std::string::npos);
  EXPECT_NE(error_of([] { parse("kinestat: 1\nkind: structure\nadjacency: [[0, 1], [1, 0]]\nextra: 1\n"); })
                .find("unknown key 'extra'"),
            std::string::npos);
  EXPECT_NE(error_of([] { parse("kinestat: 1\nkind: structure\ndimension: spatial\nbodies: [f, a]\npairs:\n  - {between: [f, a], pair: higher}\n"); })
                .find("spatial higher pair needs 'freedoms'"),
            std::string::npos);
}

}  // namespace
}  // namespace kinestat::io
