// SPDX-License-Identifier: BSD-3-Clause
// The SPACAR reader takes the caller's limit on model files (ImportOptions::max_input_bytes,
// the command's --max-input-size; issue 41, item 4) instead of a fixed 64 MiB of its own: a
// file over a given limit is refused with one line naming the file and the limit (exit 2), the
// same file read when the limit is raised, also past 64 MiB.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/spacar_reader.hpp"
#include "support/cli_run.hpp"

namespace kinestat::testing::spacar_input_limit {
namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A truss triangle with nodes 1 and 2 fixed. By hand: node 3's three coordinates against two
// independent trusses leave one motion (the turn about the line 1-2), and truss 1 between two
// fixed nodes is one self-stress.
const std::string kTriangle = "X 1 0 0 0\nX 2 1 0 0\nX 3 0 1 0\nTRUSS 1 1 2\nTRUSS 2 2 3\nTRUSS 3 3 1\nFIX 1\nFIX 2\nEND\n";

// One line, exit 2, nothing on standard output; the line names `path` and the limit `limit`.
void expect_refused(const CliRun& r, const std::string& path, const std::string& limit) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  EXPECT_TRUE(has(r.err, path + ": error: the input is larger than the " + limit + " limit on model files")) << r.err;
  EXPECT_TRUE(has(r.err, "--max-input-size")) << r.err;
}

// The triangle's counts as the command's JSON gives them.
void expect_triangle_counts(const CliRun& r) {
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "\"mechanisms\": 1")) << r.out.substr(0, 2000);
  EXPECT_TRUE(has(r.out, "\"self_stresses\": 1")) << r.out.substr(0, 2000);
}

TEST(SpacarInputLimit, ParserTakesTheCallersLimit) {
  io::ImportOptions options;
  options.max_input_bytes = kTriangle.size() - 1;
  try {
    (void)io::parse_spacar("t.dat", kTriangle, options);
    ADD_FAILURE() << "a text over the limit was read";
  } catch (const io::InputError& error) {
    EXPECT_TRUE(has(error.what(), "t.dat: error: the input is larger than the " + std::to_string(kTriangle.size() - 1) +
                                      " bytes limit on model files"))
        << error.what();
  }
  options.max_input_bytes = kTriangle.size();
  const io::SpacarImport imported = io::parse_spacar("t.dat", kTriangle, options);
  EXPECT_EQ(imported.model.nodes.size(), 3u);
  EXPECT_EQ(imported.model.elements.size(), 3u);
}

TEST(SpacarInputLimit, CommandRefusesAFileOverTheGivenLimitAndReadsItWhenRaised) {
  // 3000 bytes: the triangle and comment lines.
  std::string text = kTriangle;
  while (text.size() < 3000) text += "% " + std::string(77, 'c') + "\n";
  text.resize(2999);
  text += "\n";
  const std::string path = write_temp_file("triangle-3000.dat", text);
  ASSERT_EQ(std::filesystem::file_size(path), 3000u);
  expect_refused(run_cli("analyze " + path + " --max-input-size 2KiB --json"), path, "2048 bytes");
  expect_refused(run_cli("analyze " + path + " --max-input-size 2999 --json"), path, "2999 bytes");
  expect_triangle_counts(run_cli("analyze " + path + " --max-input-size 3000 --json"));
  expect_triangle_counts(run_cli("analyze " + path + " --max-input-size 4KiB --json"));
}

TEST(SpacarInputLimit, FileLargerThan64MiBIsReadWhenTheLimitIsRaised) {
  // The triangle, then 65 comment lines of 1 MiB each (SPACAR's '%' comments).
  const std::string path = (scratch_folder() / "triangle-65MiB.dat").string();
  {
    std::ofstream out(path, std::ios::binary);
    out << kTriangle;
    const std::string line = "%" + std::string((std::size_t{1} << 20) - 2, 'c') + "\n";
    for (int i = 0; i < 65; ++i) out << line;
  }
  expect_refused(run_cli("analyze " + path + " --json"), path, "64 MiB");
  expect_triangle_counts(run_cli("analyze " + path + " --max-input-size 80MiB --json"));
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace kinestat::testing::spacar_input_limit
