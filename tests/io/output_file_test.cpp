// SPDX-License-Identifier: BSD-3-Clause
// Output files (`-o`): devices and FIFOs are written in place and never replaced, symbolic
// links are followed, parallel writers never collide, and a failed write leaves nothing behind
// and says why. Device nodes are made with mknod in a private scratch folder, never in /dev.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/output_file.hpp"
#include "support/cli_run.hpp"

namespace kinestat::io {
namespace {

namespace fs = std::filesystem;

// A fresh folder of this test's own, removed at the end.
class Scratch {
 public:
  Scratch() {
    std::string pattern = (fs::temp_directory_path() / "kinestat-output-XXXXXX").string();
    path_ = ::mkdtemp(pattern.data());
  }
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  fs::path operator/(const std::string& name) const { return path_ / name; }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& entry : fs::directory_iterator(path_)) out.push_back(entry.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  fs::path path_;
};

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A character device node like /dev/null (1, 3), /dev/zero (1, 5) or /dev/full (1, 7), or
// false where the test may not create one (not root).
bool make_device(const fs::path& path, unsigned minor) {
  return ::mknod(path.c_str(), S_IFCHR | 0666, makedev(1, minor)) == 0;
}

TEST(OutputFile, RegularFileIsReplacedWhole) {
  Scratch dir;
  std::ofstream(dir / "report.json") << "old";
  write_file_atomically((dir / "report.json").string(), "new report\n");
  EXPECT_EQ(contents(dir / "report.json"), "new report\n");
  EXPECT_EQ(dir.names(), std::vector<std::string>{"report.json"});  // no temporary left
}

TEST(OutputFile, NewFileGetsTheUsualPermissions) {
  Scratch dir;
  const mode_t mask = ::umask(022);
  write_file_atomically((dir / "new.txt").string(), "x");
  ::umask(mask);
  EXPECT_EQ(fs::status(dir / "new.txt").permissions(),
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read);
}

TEST(OutputFile, DeviceIsWrittenNotReplaced) {
  Scratch dir;
  if (!make_device(dir / "null", 3)) GTEST_SKIP() << "mknod needs root";
  write_file_atomically((dir / "null").string(), "a report\n");
  struct stat info {};
  ASSERT_EQ(::stat((dir / "null").c_str(), &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode));  // still the device, not a file holding the report
  EXPECT_EQ(dir.names(), std::vector<std::string>{"null"});
}

TEST(OutputFile, FullDeviceFailsWithTheSystemsReason) {
  Scratch dir;
  if (!make_device(dir / "full", 7)) GTEST_SKIP() << "mknod needs root";
  try {
    write_file_atomically((dir / "full").string(), std::string(100000, 'x'));
    FAIL() << "writing to a full device succeeded";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(std::strerror(ENOSPC)), std::string::npos) << error.what();
  }
  struct stat info {};
  ASSERT_EQ(::stat((dir / "full").c_str(), &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode));
}

TEST(OutputFile, FifoIsWrittenInPlace) {
  Scratch dir;
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = contents(dir / "pipe"); });
  write_file_atomically((dir / "pipe").string(), "through the pipe\n");
  reader.join();
  EXPECT_EQ(received, "through the pipe\n");
  EXPECT_TRUE(fs::is_fifo(dir / "pipe"));
}

TEST(OutputFile, SymbolicLinksAreFollowedToTheirTarget) {
  Scratch dir;
  std::ofstream(dir / "target.txt") << "old";
  fs::create_symlink("target.txt", dir / "link.txt");
  write_file_atomically((dir / "link.txt").string(), "new");
  EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
  EXPECT_EQ(contents(dir / "target.txt"), "new");
  // A link whose target does not exist yet creates the target.
  fs::create_symlink("later.txt", dir / "dangling.txt");
  write_file_atomically((dir / "dangling.txt").string(), "created");
  EXPECT_TRUE(fs::is_symlink(dir / "dangling.txt"));
  EXPECT_EQ(contents(dir / "later.txt"), "created");
}

TEST(OutputFile, ParallelWritersNeverCollide) {
  Scratch dir;
  const std::string target = (dir / "shared.json").string();
  std::vector<std::thread> writers;
  std::vector<int> failures(16, 0);
  for (int t = 0; t < 16; ++t) {
    writers.emplace_back([&, t] {
      for (int round = 0; round < 20; ++round) {
        try {
          write_file_atomically(target, std::string(10000, static_cast<char>('a' + t)));
        } catch (const InputError&) {
          ++failures[static_cast<std::size_t>(t)];
        }
      }
    });
  }
  for (auto& w : writers) w.join();
  for (int f : failures) EXPECT_EQ(f, 0);
  const std::string last = contents(target);
  ASSERT_EQ(last.size(), 10000u);
  EXPECT_EQ(last.find_first_not_of(last[0]), std::string::npos);  // one writer's text, whole
  EXPECT_EQ(dir.names(), std::vector<std::string>{"shared.json"});
}

TEST(OutputFile, MissingFolderSaysWhy) {
  Scratch dir;
  try {
    write_file_atomically((dir / "no-such-folder" / "out.txt").string(), "x");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(std::strerror(ENOENT)), std::string::npos) << error.what();
  }
}

TEST(OutputFile, FolderAsTargetIsRefused) {
  Scratch dir;
  fs::create_directory(dir / "sub");
  EXPECT_THROW(write_file_atomically((dir / "sub").string(), "x"), InputError);
  EXPECT_TRUE(fs::is_directory(dir / "sub"));
}

// A write that fails half-way (here: the file size limit of the process) removes what it
// wrote, keeps the old file and names the reason. Run in a child so the limit stays there.
TEST(OutputFile, FailedWriteRemovesItsTemporaryAndKeepsTheOldFile) {
  Scratch dir;
  std::ofstream(dir / "report.txt") << "the old report";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    try {
      write_file_atomically((dir / "report.txt").string(), std::string(1 << 20, 'x'));
      ::_exit(10);
    } catch (const InputError& error) {
      ::_exit(std::string(error.what()).find(std::strerror(EFBIG)) != std::string::npos ? 0 : 11);
    }
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(contents(dir / "report.txt"), "the old report");
  EXPECT_EQ(dir.names(), std::vector<std::string>{"report.txt"});
}

TEST(OutputFile, CliWritesToADeviceWithoutReplacingIt) {
  Scratch dir;
  if (!make_device(dir / "null", 3)) GTEST_SKIP() << "mknod needs root";
  const auto run = testing::run_cli("analyze " + testing::example_path("four-bar-planar.yaml") + " -o " +
                                    (dir / "null").string());
  EXPECT_EQ(run.exit_code, 0) << run.err;
  struct stat info {};
  ASSERT_EQ(::stat((dir / "null").c_str(), &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode));
}

}  // namespace
}  // namespace kinestat::io
