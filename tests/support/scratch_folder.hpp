// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// One private scratch folder per test process, removed with its contents when the process ends,
// so that a run of the suite leaves nothing behind in the system's temporary folder.

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace kinestat::testing {

/// This process's scratch folder: made by mkdtemp under the system's temporary folder on first
/// use (so parallel test processes never share one) and removed when the process exits. A
/// forked child (a death test) inherits the path but never removes it: only the process that
/// made the folder does.
inline const std::filesystem::path& scratch_folder() {
  struct Folder {
    std::filesystem::path path;
    pid_t owner = ::getpid();
    Folder() {
      std::string pattern = (std::filesystem::temp_directory_path() / "kinestat-test-XXXXXX").string();
      if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot make a scratch folder " + pattern);
      path = pattern;
    }
    Folder(const Folder&) = delete;
    Folder& operator=(const Folder&) = delete;
    ~Folder() {
      if (::getpid() != owner) return;
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Folder folder;
  return folder.path;
}

/// A folder of this name inside scratch_folder(), made if missing.
inline std::filesystem::path scratch_subfolder(const std::string& name) {
  const auto folder = scratch_folder() / name;
  std::filesystem::create_directories(folder);
  return folder;
}

}  // namespace kinestat::testing
