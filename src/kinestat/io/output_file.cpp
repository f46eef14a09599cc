// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/output_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "kinestat/io/input_error.hpp"

namespace kinestat::io {

namespace {

namespace fs = std::filesystem;

// Linux gives up on symbolic link chains at 40 links as well (ELOOP).
constexpr int kMaxSymbolicLinks = 40;

[[noreturn]] void fail(const std::string& path, const std::string& what, int error) {
  throw InputError({path, 0, 0}, fmt::format("cannot write output file: {}: {}", what, std::strerror(error)));
}

// The file a path finally names: symbolic links followed, even to a target that does not
// exist yet (which is then created).
fs::path resolve_links(const std::string& path) {
  fs::path current(path);
  for (int i = 0; i < kMaxSymbolicLinks; ++i) {
    std::error_code error;
    if (!fs::is_symlink(fs::symlink_status(current, error))) return current;
    const fs::path target = fs::read_symlink(current, error);
    if (error) fail(path, "cannot follow the symbolic link", error.value());
    current = target.is_absolute() ? target : current.parent_path() / target;
  }
  fail(path, "cannot follow the symbolic link", ELOOP);
}

// The process's file mode creation mask, read without changing it (umask() can only be read
// by setting it, which would race with other threads creating files).
mode_t current_umask() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("Umask:", 0) == 0) return static_cast<mode_t>(std::strtoul(line.c_str() + 6, nullptr, 8));
  }
  return 022;
}

// Writes all of `content` to `fd`; returns 0 or the errno of the failure.
int write_all(int fd, const std::string& content) {
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

// A device, FIFO or socket: written in place (there is nothing to rename over it).
void write_in_place(const std::string& path, const fs::path& target, const std::string& content) {
  const int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) fail(path, "cannot open it for writing", errno);
  const int error = write_all(fd, content);
  const int close_error = ::close(fd) != 0 ? errno : 0;
  if (error != 0) fail(path, "writing failed", error);
  if (close_error != 0) fail(path, "writing failed", close_error);
}

void write_by_rename(const std::string& path, const fs::path& target, const struct stat* existing,
                     const std::string& content) {
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  // mkstemp makes the name unique, so parallel runs writing the same target never collide.
  std::string pattern = (folder / ("." + target.filename().string() + ".kinestat-XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) fail(path, fmt::format("cannot create a file in the folder '{}'", folder.string()), errno);
  const std::string temporary(name.data());
  auto give_up = [&](const std::string& what, int error) {
    ::unlink(temporary.c_str());
    fail(path, what, error);
  };
  // mkstemp creates the file for its owner only; give it the mode the target has (or would
  // get from the umask as a new file).
  mode_t mode = 0;
  if (existing) {
    mode = existing->st_mode & 07777;
  } else {
    mode = 0666 & ~current_umask();
  }
  if (::fchmod(fd, mode) != 0) {
    const int error = errno;
    ::close(fd);
    give_up("cannot set the permissions of the temporary file", error);
  }
  int error = write_all(fd, content);
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) give_up("writing failed", error);
  if (::rename(temporary.c_str(), target.c_str()) != 0) give_up("cannot rename the temporary file over it", errno);
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& content) {
  const fs::path target = resolve_links(path);
  struct stat info {};
  if (::stat(target.c_str(), &info) == 0) {
    if (S_ISDIR(info.st_mode)) {
      throw InputError({path, 0, 0}, "cannot write output file: this is a folder; give the name of the file to write, "
                                     "e.g. 'report.json'");
    }
    if (!S_ISREG(info.st_mode)) return write_in_place(path, target, content);
    return write_by_rename(path, target, &info, content);
  }
  if (errno != ENOENT) fail(path, "cannot inspect it", errno);
  write_by_rename(path, target, nullptr, content);
}

void refuse_output_over_inputs(const std::string& output, const std::vector<std::string>& inputs) {
  if (output.empty() || output == "-") return;
  struct stat written {};
  if (::stat(output.c_str(), &written) != 0 || !S_ISREG(written.st_mode)) return;
  for (const std::string& input : inputs) {
    struct stat read {};
    if (input.empty() || input == "-" || ::stat(input.c_str(), &read) != 0) continue;
    if (read.st_dev == written.st_dev && read.st_ino == written.st_ino)
      throw InputError({output, 0, 0}, fmt::format("the output file is the input file '{}': refusing to replace it with the output; "
                                                   "name another output file",
                                                   input));
  }
}

}  // namespace kinestat::io
