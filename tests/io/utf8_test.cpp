// SPDX-License-Identifier: BSD-3-Clause
// Model files are UTF-8. A name with bytes that are not UTF-8 (a Latin-1 export, a corrupted
// file) used to pass the reader and make the JSON report throw (exit 3; found by the fuzzer,
// fuzz/seeds/model/regression-invalid-utf8-name.yaml); now it is an input error with its
// position, as are control characters YAML does not allow; names in other scripts are
// carried through to every report unchanged.
#include <gtest/gtest.h>

#include <string>

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/report/json_text.hpp"
#include "support/cli_run.hpp"

namespace kinestat {
namespace {

std::string position_of_error(const std::string& text) {
  try {
    (void)io::YamlFile::parse("in.yaml", text);
  } catch (const io::InputError& error) {
    return error.what();
  }
  return "accepted";
}

TEST(Utf8, InvalidBytesAreAnErrorWithTheirPosition) {
  // Latin-1 'ä' (0xE4) on line 2, after the 8 characters of 'name: "M'.
  EXPECT_EQ(position_of_error("kinestat: 1\nname: \"M\xE4rz\"\n").rfind("in.yaml:2:9: error: byte 0xE4 is not UTF-8", 0), 0u)
      << position_of_error("kinestat: 1\nname: \"M\xE4rz\"\n");
  // A stray continuation byte, a truncated sequence at the end, an overlong '/', a UTF-16
  // surrogate, a code point above U+10FFFF: all rejected.
  for (const std::string bad : {"name: \x9B\n", "name: ab\xE2\x82", "name: \xC0\xAF\n", "name: \xED\xA0\x80\n",
                                "name: \xF4\x90\x80\x80\n"})
    EXPECT_NE(position_of_error(bad).find("is not UTF-8"), std::string::npos) << position_of_error(bad);
  // Column counts characters, not bytes: two 2-byte characters before the bad byte.
  EXPECT_EQ(position_of_error("name: \xC3\xA4\xC3\xB6\xFF\n").rfind("in.yaml:1:9:", 0), 0u);
}

TEST(Utf8, ControlCharactersAreAnError) {
  // yaml-cpp turned "leg3 <0x11> <NUL> _upper" into a name with a lone byte 0xA0 (found by the
  // fuzzer, fuzz/seeds/model/regression-nul-in-name.yaml). YAML allows no C0 controls but tab,
  // line feed and carriage return.
  EXPECT_EQ(position_of_error(std::string("name: leg3\x11\0_upper\n", 19)).rfind("in.yaml:1:11: error: control character U+0011", 0), 0u)
      << position_of_error(std::string("name: leg3\x11\0_upper\n", 19));
  EXPECT_NE(position_of_error("name: a\x7F\n").find("control character U+007F"), std::string::npos);
  EXPECT_EQ(position_of_error("kinestat: 1\r\nname:\tx\r\n"), "accepted");  // tabs and CRLF are fine
  const auto run = testing::run_cli("analyze --json " + std::string(KINESTAT_SOURCE_DIR) + "/fuzz/seeds/model/regression-nul-in-name.yaml");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_NE(run.err.find("control character U+0011"), std::string::npos) << run.err;
}

TEST(Utf8, WellFormedNamesInOtherScriptsAreKept) {
  const std::string model =
      "kinestat: 1\nkind: structure\nname: \"Getriebe \xC3\xA4 \xE8\xBD\xB4 \xF0\x9F\x94\xA7\"\n"
      "bodies: [Gestell, Kurbel, Koppel, Schwinge]\n"
      "pairs:\n  - {between: [Gestell, Kurbel], pair: lower, inputs: 1}\n  - {between: [Kurbel, Koppel], pair: lower}\n"
      "  - {between: [Koppel, Schwinge], pair: lower}\n  - {between: [Schwinge, Gestell], pair: lower}\n";
  const std::string path = testing::write_temp_file("utf8-model.yaml", model);
  const auto run = testing::run_cli("structure --json " + path);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("Getriebe \xC3\xA4 \xE8\xBD\xB4 \xF0\x9F\x94\xA7"), std::string::npos) << run.out;
}

TEST(Utf8, TheCrashingFileIsRejectedCleanly) {
  const auto run = testing::run_cli("structure --json " + std::string(KINESTAT_SOURCE_DIR) +
                                    "/fuzz/seeds/model/regression-invalid-utf8-name.yaml");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_NE(run.err.find("regression-invalid-utf8-name.yaml:5:"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("is not UTF-8"), std::string::npos) << run.err;
}

TEST(Utf8, JsonTextReplacesBytesThatAreNotUtf8) {
  const nlohmann::ordered_json value = {{"name", std::string("a\x9B" "b")}};
  EXPECT_EQ(report::json_text(value, -1), "{\"name\":\"a\xEF\xBF\xBD" "b\"}");
  EXPECT_EQ(report::json_text(value), "{\n  \"name\": \"a\xEF\xBF\xBD" "b\"\n}\n");
}

}  // namespace
}  // namespace kinestat
