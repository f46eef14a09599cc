// SPDX-License-Identifier: BSD-3-Clause
// Hostile or huge input fails cleanly with a position, without stack overflow, hang or
// memory blow-up: deep flow and block nesting, alias expansion ("billion laughs"), long
// strings and huge numbers.
#include <gtest/gtest.h>

#include <string>

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace kinestat::io {
namespace {

void expect_error(const std::string& text, const std::string& message_part) {
  try {
    (void)YamlFile::parse("in.yaml", text);
    FAIL() << "accepted: " << text.substr(0, 80);
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(message_part), std::string::npos) << error.what();
    EXPECT_EQ(std::string(error.what()).rfind("in.yaml:", 0), 0u);
  }
}

TEST(YamlLimits, DeepFlowNesting) { expect_error("a: " + std::string(100000, '[') + std::string(100000, ']'), "nesting deeper"); }

TEST(YamlLimits, DeepBlockNesting) {
  expect_error("a:\n" + std::string(100000, '-') + " x\n", "block nesting deeper");
  std::string indented = "a:\n";
  for (int i = 1; i < 700; ++i) indented += std::string(static_cast<std::size_t>(i), ' ') + "b" + std::to_string(i) + ":\n";
  expect_error(indented, "block nesting deeper");
}

TEST(YamlLimits, AliasExpansion) {
  std::string bomb = "kinestat: 1\na0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i < 9; ++i) {
    const std::string prev = "*a" + std::to_string(i - 1);
    bomb += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [" + prev;
    for (int j = 0; j < 9; ++j) bomb += ", " + prev;
    bomb += "]\n";
  }
  expect_error(bomb, "expands to more than");
}

TEST(YamlLimits, LongStringsAndHugeNumbersAreHandled) {
  const auto file = YamlFile::parse("in.yaml", "kinestat: 1\nname: " + std::string(1 << 20, 'x') + "\nx: 1e999\ny: 1e-999\n");
  EXPECT_THROW((void)file.number(file.root()["x"], "x"), InputError);  // beyond double range
  EXPECT_THROW((void)file.number(file.root()["y"], "y"), InputError);  // too small to be a length
}

TEST(YamlLimits, ExactDecimals) {
  EXPECT_EQ(*parse_exact_decimal("-1.25e-3"), mpq_class(-1, 800));
  EXPECT_EQ(*parse_exact_decimal("0.1"), mpq_class(1, 10));
  EXPECT_EQ(*parse_exact_decimal("000120"), mpq_class(120));
  EXPECT_FALSE(parse_exact_decimal("1/3"));
  EXPECT_FALSE(parse_exact_decimal(".nan"));
  EXPECT_FALSE(parse_exact_decimal("0x10"));
  EXPECT_FALSE(parse_exact_decimal("1e"));
  EXPECT_EQ(significant_digits("0.8660254037844386"), 16);
  EXPECT_EQ(significant_digits("-1.50e3"), 3);
  EXPECT_EQ(significant_digits("0"), 1);
}

}  // namespace
}  // namespace kinestat::io
