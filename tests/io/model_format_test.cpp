// SPDX-License-Identifier: BSD-3-Clause
// Which reader an .xml model goes to (io/model_format): its root element, looked for in the
// file's first kXmlRootSearchBytes only, so that a large file is refused by its reader with the
// user's --max-input-size, never by the format detection at a fixed size (issue 41, item 4).

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/model_format.hpp"
#include "kinestat/io/urdf_reader.hpp"
#include "support/cli_run.hpp"

namespace kinestat::io::model_format_test {
namespace {

namespace fs = std::filesystem;
using testing::run_cli;
using testing::write_temp_file;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The message of the InputError model_format throws for `path`, or "accepted".
std::string error_of(const std::string& path) {
  try {
    (void)model_format(path);
    return "accepted";
  } catch (const InputError& error) {
    return error.what();
  }
}

// An XML declaration, then a comment that fills the file up to byte `root_at`, then `rest`.
std::string after_prolog(std::size_t root_at, const std::string& rest) {
  const std::string declaration = "<?xml version=\"1.0\"?>\n<!-- ";
  const std::string close = " -->";
  return declaration + std::string(root_at - declaration.size() - close.size(), 'c') + close + rest;
}

TEST(ModelFormat, RootAfterALongCommentIsFoundInThePrefix) {
  // 900 KiB of licence comment and a doctype before the root: inside the 1 MiB searched.
  const std::size_t at = 900 * 1024;
  const std::string tail = "\n<!DOCTYPE model>\n";
  EXPECT_EQ(model_format(write_temp_file("long-prolog-robot.xml", after_prolog(at, tail + "<robot name=\"r\"/>\n"))), ModelFormat::urdf);
  EXPECT_EQ(model_format(write_temp_file("long-prolog-mujoco.xml", after_prolog(at, tail + "<mujoco model=\"m\"/>\n"))),
            ModelFormat::mjcf);
  EXPECT_EQ(model_format(write_temp_file("long-prolog-sdf.XML", after_prolog(at, tail + "<sdf version=\"1.6\"/>\n"))),
            ModelFormat::sdformat);
}

TEST(ModelFormat, RootPastThePrefixIsRefusedSayingWhatWasExpected) {
  const std::string path = write_temp_file("late-root.xml", after_prolog(kXmlRootSearchBytes + 4096, "<robot name=\"r\"/>\n"));
  const std::string message = error_of(path);
  EXPECT_EQ(message, path + ":1:1: error: no root element in the first 1 MiB of this .xml file (after its declaration, "
                            "comments and doctype): expected <mujoco> (MJCF), <robot> (URDF) or <sdf> (SDFormat) within them");
}

TEST(ModelFormat, RootNameAtTheEndOfThePrefixIsReadWholeOrNotAtAll) {
  // "<mujoco" starts 4 bytes before the end of the prefix: only "<muj" was read, which is no
  // name to go by (not a <muj> root).
  const std::size_t end = kXmlRootSearchBytes;
  const std::string cut = error_of(write_temp_file("cut-root.xml", after_prolog(end - 4, "<mujoco model=\"m\"/>\n")));
  EXPECT_TRUE(has(cut, "no root element in the first 1 MiB")) << cut;
  // "<mujoco>" ends on the prefix's last byte: the whole name was read.
  EXPECT_EQ(model_format(write_temp_file("whole-root.xml", after_prolog(end - 8, "<mujoco>\n</mujoco>\n"))), ModelFormat::mjcf);
}

TEST(ModelFormat, OtherRootsFoldersAndMissingFilesSayWhatIsWrong) {
  const std::string scene = write_temp_file("scene.xml", "<?xml version=\"1.0\"?>\n<scene/>\n");
  // The position is the root's '<': line 2 after the declaration; column 3 after two spaces.
  EXPECT_EQ(error_of(scene), scene + ":2:1: error: an .xml file with a <scene> root is not a format kinestat reads; expected "
                                     "<mujoco>, <robot> or <sdf>");
  const std::string indented = write_temp_file("indented.xml", "<!-- a\n comment -->\n\n  <world/>\n");
  EXPECT_TRUE(has(error_of(indented), indented + ":4:3: error: an .xml file with a <world> root")) << error_of(indented);
  const std::string text = write_temp_file("text.xml", "just words\n");
  EXPECT_EQ(error_of(text), text + ":1:1: error: an .xml file must be MJCF (<mujoco>), URDF (<robot>) or SDFormat (<sdf>)");
  const fs::path folder = testing::scratch_folder() / "folder.xml";
  fs::create_directories(folder);
  EXPECT_TRUE(has(error_of(folder.string()), "this is a folder, not a file")) << error_of(folder.string());
  const std::string missing = (testing::scratch_folder() / "missing.xml").string();
  EXPECT_TRUE(has(error_of(missing), missing + ": error: cannot open file for reading")) << error_of(missing);
}

// A named pipe called .xml is refused at once with exit 2 rather than read twice: its root
// element would be read by the format detection, and the reader's second open would wait for
// another writer for ever. The test holds the pipe open for writing itself (O_RDWR does not wait
// on Linux), so that the detection's open does not wait either, and writes nothing.
TEST(ModelFormat, PipeNamedXmlIsRefusedNotReadTwice) {
  const fs::path pipe = testing::scratch_folder() / "pipe.xml";
  fs::remove(pipe);
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  const int writer = ::open(pipe.c_str(), O_RDWR | O_CLOEXEC);
  ASSERT_GE(writer, 0);
  const std::string message = error_of(pipe.string());
  ::close(writer);
  fs::remove(pipe);
  EXPECT_EQ(message, pipe.string() + ": error: an .xml model must be a regular file (this is a pipe or device): its root "
                                     "element is read first to tell MJCF, URDF and SDFormat apart, then the file is read "
                                     "again; save it to a file, or name it .urdf or .sdf");
}

// A 100 MiB .xml (sparse: its size costs no disk) is told apart by its first bytes, then refused
// by the URDF reader at the user's limit: one line naming the file and that limit, exit 2.
TEST(ModelFormat, LargeXmlIsRefusedByItsReaderAtTheUsersLimit) {
  const std::string path = write_temp_file("large.xml", "<robot name=\"r\">\n");
  fs::resize_file(path, std::uintmax_t{100} << 20);
  EXPECT_EQ(model_format(path), ModelFormat::urdf);  // not refused for its size here
  const testing::CliRun r = run_cli("analyze " + path + " --max-input-size 2MiB");
  fs::remove(path);
  if (!urdf_reader_built_in()) GTEST_SKIP() << r.err;
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;  // one line
  EXPECT_TRUE(has(r.err, path + ": error: the input is larger than the 2 MiB limit on model files")) << r.err;
}

}  // namespace
}  // namespace kinestat::io::model_format_test
