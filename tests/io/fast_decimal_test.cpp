// SPDX-License-Identifier: BSD-3-Clause
// The readers' fast path for numbers (io::decimal_toward_zero, YamlFile::plain_numbers) gives
// exactly the double the exact path gives: GMP's exact rational of the literal converted by
// mpq_get_d (rounding towards zero), compared bit for bit on fixed and seeded random literals.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "kinestat/io/yaml_support.hpp"
#include "kinestat/linalg/seeded_random.hpp"

namespace kinestat::io {
namespace {

std::uint64_t bits_of(double value) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

// The exact path's double: GMP's rational of the literal, converted by mpq_get_d.
double exact_double(const std::string& literal) {
  const std::optional<mpq_class> exact = parse_exact_decimal(literal);
  EXPECT_TRUE(exact.has_value()) << literal;
  return exact ? exact->get_d() : 0.0;
}

// Whenever the fast path answers, its answer is GMP's, bit for bit.
void expect_same_as_gmp(const std::string& literal) {
  const std::optional<double> fast = decimal_toward_zero(literal);
  if (!fast) return;
  EXPECT_EQ(bits_of(*fast), bits_of(exact_double(literal))) << literal << ": fast " << *fast;
}

TEST(FastDecimal, FixedLiteralsRoundTowardsZeroAsGmp) {
  // 0.1 is 0.1000000000000000055...: the nearest double is above it, the truncated one below.
  ASSERT_TRUE(decimal_toward_zero("0.1").has_value());
  EXPECT_EQ(*decimal_toward_zero("0.1"), std::nextafter(0.1, 0.0));
  EXPECT_EQ(*decimal_toward_zero("-0.1"), -std::nextafter(0.1, 0.0));
  // 0.5, 3 and 1e22 are doubles: no rounding at all.
  EXPECT_EQ(*decimal_toward_zero("0.5"), 0.5);
  EXPECT_EQ(*decimal_toward_zero("+3"), 3.0);
  EXPECT_EQ(*decimal_toward_zero("1e22"), 1e22);
  // 2^53 + 1 lies halfway between two doubles; towards zero is 2^53.
  EXPECT_EQ(*decimal_toward_zero("9007199254740993"), 9007199254740992.0);
  // Zero has no sign in GMP.
  EXPECT_EQ(bits_of(*decimal_toward_zero("-0.000")), bits_of(0.0));
  for (const char* literal : {"0.866025", "500.5626834", "-1.50e3", "1.", ".5", "00012.50", "1E-5", "123456789.123456789",
                              "0.8660254037844386", "2.718281828459045e-7", "6.02214076e23", "1e-38", "1e38"})
    expect_same_as_gmp(literal);
}

TEST(FastDecimal, NotDecimalsAndOutOfItsRangeAreLeftToTheExactPath) {
  for (const char* literal : {"", "-", ".", "e5", "1e", "1.5e+", "0x10", "1,5", "inf", ".nan", "1 ", "12345678901234567890",
                              "1e-400", "1e400", "1e39"})
    EXPECT_FALSE(decimal_toward_zero(literal).has_value()) << literal;
}

TEST(FastDecimal, SeededRandomLiteralsAgreeWithGmp) {
  linalg::SeededRandom random(20261126);
  int answered = 0, coordinates = 0, coordinates_answered = 0;
  for (int k = 0; k < 200000; ++k) {
    const int digits = 1 + static_cast<int>(random.next() % 19);
    std::string mantissa;
    for (int d = 0; d < digits; ++d) mantissa += static_cast<char>('0' + random.next() % 10);
    const int point = static_cast<int>(random.next() % static_cast<std::uint64_t>(digits + 1));
    std::string literal = (random.next() % 2 == 0 ? "-" : "") + mantissa.substr(0, static_cast<std::size_t>(point)) + "." +
                          mantissa.substr(static_cast<std::size_t>(point));
    const bool exponent = random.next() % 3 == 0;
    const auto e = static_cast<int>(random.integer(40));
    if (exponent) literal += "e" + std::to_string(e);
    expect_same_as_gmp(literal);
    answered += decimal_toward_zero(literal).has_value() ? 1 : 0;
    // What coordinates in model files look like: up to 12 digits, no exponent.
    if (!exponent && digits <= 12) {
      ++coordinates;
      coordinates_answered += decimal_toward_zero(literal).has_value() || mantissa.find_first_not_of('0') == std::string::npos ? 1 : 0;
    }
  }
  EXPECT_EQ(coordinates_answered, coordinates);  // every coordinate-like literal takes the fast path
  EXPECT_GT(answered, 100000);
}

TEST(FastDecimal, PlainNumbersGiveWhatNumbersGives) {
  const YamlFile file = YamlFile::parse("in.yaml", "a: [0.1, -2.5e-3, 7]\nb: [0.1, x]\nc: [1, 2]\nd: ['0.3', 1e-400]\n");
  double values[3] = {};
  ASSERT_TRUE(file.plain_numbers(file.root()["a"], 3, values));
  const auto exact = file.numbers(file.root()["a"], "a", {3});
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(bits_of(values[i]), bits_of(exact[i].value));
  EXPECT_FALSE(file.plain_numbers(file.root()["b"], 2, values));  // not a number: the exact path's error
  EXPECT_FALSE(file.plain_numbers(file.root()["c"], 3, values));  // wrong length
  EXPECT_FALSE(file.plain_numbers(file.root()["d"], 2, values));  // out of the fast range
  EXPECT_FALSE(file.plain_numbers(file.root(), 2, values));       // not a list
}

TEST(FastDecimal, KeysAllowedMatchesCheckKeys) {
  const YamlFile file = YamlFile::parse("in.yaml", "a: {x: 1, y: 2}\nb: {x: 1, z: 2}\nc: {x: 1, x: 2}\nd: [1]\n");
  const auto passes = [&](const char* key) {
    try {
      file.check_keys(file.root()[key], "it", {"x", "y"});
      return true;
    } catch (const InputError&) {
      return false;
    }
  };
  for (const char* key : {"a", "b", "c", "d"}) EXPECT_EQ(file.keys_allowed(file.root()[key], {"x", "y"}), passes(key)) << key;
}

}  // namespace
}  // namespace kinestat::io
