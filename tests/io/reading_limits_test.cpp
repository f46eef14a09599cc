// SPDX-License-Identifier: BSD-3-Clause
// The reading layer enforces every limit while it reads (issue 16): bytes through a bounded
// reader (devices, FIFOs, standard input), nesting, aliases counted as they expand, one
// document per file, strings checked after unescaping, and messages that say what is wrong.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <sstream>
#include <string>
#include <thread>

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "support/cli_run.hpp"

namespace kinestat::io {
namespace {

namespace fs = std::filesystem;

// The message of the InputError that parsing `text` throws, or "accepted".
std::string error_of(const std::string& text, const ReadingLimits& limits = {}) {
  try {
    (void)YamlFile::parse("in.yaml", text, limits);
    return "accepted";
  } catch (const InputError& error) {
    return error.what();
  }
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(ReadingLimits, SelfReferencingAliasIsRefusedAtOnce) {
  const std::string message = error_of("kinestat: 1\na: &a [x, *a]\n");
  EXPECT_EQ(message.rfind("in.yaml:2:11: error: the alias '*a' refers to the list or map that contains it", 0), 0u)
      << message;
}

// Ten aliases of ten aliases ...: 10^9 nodes from 1 kB. Counted as they expand, the limit is
// hit while reading; a small limit shows the count is exact: 1 + 10 scalars under `a0`.
TEST(ReadingLimits, AliasesCountAsTheNodesTheyStandFor) {
  std::string bomb = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i < 9; ++i) {
    const std::string prev = "*a" + std::to_string(i - 1);
    bomb += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [" + prev;
    for (int j = 0; j < 9; ++j) bomb += ", " + prev;
    bomb += "]\n";
  }
  EXPECT_TRUE(has(error_of(bomb), "node limit")) << error_of(bomb);
  // root map, key a0, list and 10 scalars = 13 nodes; key a1 and its list, 10 aliases of 11 = 112 more.
  ReadingLimits limits;
  limits.max_nodes = 13;
  EXPECT_EQ(error_of("a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n", limits), "accepted");
  limits.max_nodes = 12;
  EXPECT_TRUE(has(error_of("a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n", limits), "more than 12 nodes"));
  limits.max_nodes = 13 + 2 + 110;
  EXPECT_EQ(error_of("a0: &a0 [x, x, x, x, x, x, x, x, x, x]\na1: [*a0, *a0, *a0, *a0, *a0, *a0, *a0, *a0, *a0, *a0]\n", limits),
            "accepted");
  limits.max_nodes = 13 + 2 + 109;
  EXPECT_TRUE(has(error_of("a0: &a0 [x, x, x, x, x, x, x, x, x, x]\na1: [*a0, *a0, *a0, *a0, *a0, *a0, *a0, *a0, *a0, *a0]\n",
                           limits),
                  "node limit"));
}

TEST(ReadingLimits, FlatListBeyondTheNodeLimit) {
  ReadingLimits limits;
  limits.max_nodes = 1000;
  std::string list = "kinestat: 1\nx: [0";
  for (int i = 0; i < 2000; ++i) list += ",0";
  list += "]\n";
  // Refused by the scan of the raw text, before the parser runs: two content lines, then the
  // 999th comma is entry 1001; "x: [0" is 5 columns and comma k sits at column 4 + 2k.
  EXPECT_TRUE(has(error_of(list, limits), "in.yaml:2:2002: error: the document has more than 1000 entries (lines and "
                                          "items of flow lists), past the node limit (1000 nodes)"))
      << error_of(list, limits);
  // A block list: line k + 2 holds item k, entry k + 2, so entry 1001 is on line 1001.
  std::string block = "kinestat: 1\nx:\n";
  for (int i = 0; i < 2000; ++i) block += "  - 0\n";
  EXPECT_TRUE(has(error_of(block, limits), "in.yaml:1001:3: error: the document has more than 1000 entries"))
      << error_of(block, limits);
  // N = 986 block items and 10 flow items: the scan counts 2 lines, N items, the line of y and 9
  // commas = N + 12 = 998 entries; the parser meets the root, kinestat and 1, key x, its list and
  // N items, key y, its list and 10 items = N + 17 = 1003 nodes.
  std::string mixed = "kinestat: 1\nx:\n";
  for (int i = 0; i < 986; ++i) mixed += "  - 0\n";
  mixed += "y: [0, 0, 0, 0, 0, 0, 0, 0, 0, 0]\n";
  EXPECT_TRUE(has(error_of(mixed, limits), "more than 1000 nodes, the node limit")) << error_of(mixed, limits);
  // Commas inside quotes and comments separate nothing.
  std::string quoted = "kinestat: 1\nx: [\"" + std::string(2000, ',') + "\"]  # " + std::string(2000, ',') + "\n";
  EXPECT_EQ(error_of(quoted, limits), "accepted");
}

TEST(ReadingLimits, NestingLimitNamesTheLimit) {
  ReadingLimits limits;
  limits.max_nesting = 3;  // levels below the top-level map
  EXPECT_EQ(error_of("a: [[[x]]]\n", limits), "accepted");
  EXPECT_TRUE(has(error_of("a: [[[[x]]]]\n", limits), "in.yaml:1:7: error: flow nesting deeper than 3 levels, the nesting limit"))
      << error_of("a: [[[[x]]]]\n", limits);
  EXPECT_EQ(error_of("a:\n  b:\n    c:\n      d: 1\n", limits), "accepted");
  EXPECT_TRUE(has(error_of("a:\n  b:\n    c:\n      d:\n        e: 1\n", limits), "in.yaml:5:9: error: block nesting deeper than 3 levels"))
      << error_of("a:\n  b:\n    c:\n      d:\n        e: 1\n", limits);
}

TEST(ReadingLimits, SecondDocumentIsAnError) {
  EXPECT_EQ(error_of("kinestat: 1\nname: a\n---\nkinestat: 1\n").rfind("in.yaml:3:1: error: a second YAML document", 0), 0u)
      << error_of("kinestat: 1\nname: a\n---\nkinestat: 1\n");
  EXPECT_EQ(error_of("---\nkinestat: 1\n...\n"), "accepted");  // one document with its markers
}

TEST(ReadingLimits, ControlCharactersFromEscapesAreErrors) {
  EXPECT_EQ(error_of("kinestat: 1\nname: \"\\e[31mred\"\n").rfind("in.yaml:2:7: error: this string contains the control "
                                                                  "character U+001B", 0),
            0u)
      << error_of("kinestat: 1\nname: \"\\e[31mred\"\n");
  EXPECT_TRUE(has(error_of("name: \"a\\u0000b\"\n"), "control character U+0000"));
  EXPECT_TRUE(has(error_of("name: \"a\\x07b\"\n"), "control character U+0007"));
  EXPECT_TRUE(has(error_of("name: \"a\\rb\"\n"), "control character U+000D"));
  EXPECT_TRUE(has(error_of("name: \"a\\u009bb\"\n"), "control character U+009B"));  // C1 CSI
  EXPECT_TRUE(has(error_of("name: \"\\ud800\"\n"), "invalid unicode"));  // a lone surrogate
  EXPECT_EQ(error_of("name: \"tab\\there\\nand a new line\"\n"), "accepted");
}

TEST(ReadingLimits, MergeKeysAreRefusedByName) {
  const std::string text = "kinestat: 1\nbase: &b {type: spherical}\ncouplings:\n  - <<: *b\n    name: A\n";
  EXPECT_EQ(error_of(text).rfind("in.yaml:4:5: error: YAML merge keys ('<<: *anchor') are not supported", 0), 0u)
      << error_of(text);
  EXPECT_EQ(error_of("\"<<\": 1\n"), "accepted");  // a quoted key is just a name
}

TEST(ReadingLimits, CarriageReturnOnlyLineEnds) {
  EXPECT_EQ(error_of("kinestat: 1\rname: x\r").rfind("in.yaml:1:12: error: a line ends with a lone carriage return", 0), 0u)
      << error_of("kinestat: 1\rname: x\r");
  EXPECT_EQ(error_of("kinestat: 1\r\nname: x\r\n"), "accepted");
}

TEST(ReadingLimits, NumbersSayWhatIsWrong) {
  const auto file = YamlFile::parse("in.yaml", "a: 0x5\nb: 0o5\nc: " + std::string(5000, '7') + "\nd: 0." +
                                                   std::string(5000, '3') + "\ne: .nan\nf: 1e99999\n");
  const auto message = [&](const char* key) {
    try {
      (void)file.number(file.root()[key], "x");
      return std::string("accepted");
    } catch (const InputError& error) {
      return std::string(error.what());
    }
  };
  EXPECT_TRUE(has(message("a"), "hexadecimal")) << message("a");
  EXPECT_TRUE(has(message("b"), "octal")) << message("b");
  EXPECT_TRUE(has(message("c"), "more than 4000 significant digits")) << message("c");
  EXPECT_TRUE(has(message("d"), "more than 4000 significant digits")) << message("d");
  EXPECT_TRUE(has(message("e"), "must be a finite number")) << message("e");
  EXPECT_TRUE(has(message("f"), "out of range")) << message("f");
}

TEST(ReadingLimits, LongNamesAreShortenedInMessages) {
  const std::string message = error_of(std::string(70000, 'n') + "\n");  // "must be a map, found 'nnn...'"
  EXPECT_LT(message.size(), 300u);
  // A message quotes at most a 40-character excerpt of the file (issue 40).
  EXPECT_TRUE(has(message, "must be a map, found '" + std::string(40, 'n') + "\u2026'")) << message;
}

TEST(ReadingLimits, ByteLimitOnTextAndFiles) {
  ReadingLimits limits;
  limits.max_bytes = 100;
  EXPECT_TRUE(has(error_of("kinestat: 1\nname: " + std::string(100, 'x') + "\n", limits), "larger than the 100 bytes limit"));
  std::istringstream endless(std::string(1000, 'x'));
  EXPECT_THROW((void)read_model_text(endless, "<stdin>", limits), InputError);
}

TEST(ReadingLimits, FolderIsNotAModel) {
  const auto dir = fs::temp_directory_path();
  try {
    (void)read_model_text(dir.string());
    FAIL();
  } catch (const InputError& error) {
    EXPECT_TRUE(has(error.what(), "this is a folder, not a model file")) << error.what();
  }
}

// An endless FIFO is read only up to the limit (one block past it), not to its end.
TEST(ReadingLimits, EndlessFifoIsRefusedAtTheLimit) {
  std::string pattern = (fs::temp_directory_path() / "kinestat-fifo-XXXXXX").string();
  const fs::path dir = ::mkdtemp(pattern.data());
  const fs::path fifo = dir / "endless";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::signal(SIGPIPE, SIG_IGN);
  std::size_t written = 0;
  std::thread writer([&] {
    const int fd = ::open(fifo.c_str(), O_WRONLY);
    const std::string block(4096, 'x');
    while (::write(fd, block.data(), block.size()) > 0) written += block.size();
    ::close(fd);
  });
  ReadingLimits limits;
  limits.max_bytes = 1 << 20;
  try {
    (void)read_model_text(fifo.string(), limits);
    ADD_FAILURE() << "an endless FIFO was read";
  } catch (const InputError& error) {
    EXPECT_TRUE(has(error.what(), "larger than the 1 MiB limit")) << error.what();
  }
  writer.join();
  EXPECT_LT(written, std::size_t{2} << 20);
  fs::remove_all(dir);
}

TEST(ReadingLimits, ZeroDeviceIsRefusedAtTheLimit) {
  std::string pattern = (fs::temp_directory_path() / "kinestat-dev-XXXXXX").string();
  const fs::path dir = ::mkdtemp(pattern.data());
  if (::mknod((dir / "zero").c_str(), S_IFCHR | 0666, makedev(1, 5)) != 0) {
    fs::remove_all(dir);
    GTEST_SKIP() << "mknod needs root";
  }
  const auto run = testing::run_cli("analyze " + (dir / "zero").string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(has(run.err, "larger than the 64 MiB limit")) << run.err;
  fs::remove_all(dir);
}

TEST(ReadingLimits, EndlessStandardInputIsRefused) {
  const auto run = testing::run_cli("structure - < /dev/zero");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(has(run.err, "<stdin>: error: the input is larger than the 64 MiB limit")) << run.err;
}

}  // namespace
}  // namespace kinestat::io
