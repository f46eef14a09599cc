// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A file opened for reading by its POSIX descriptor, for the bounded readers of model files
// (read_model_text, the .xml format detection): one place that opens a path, refuses a folder
// and reads in blocks, so that a device or a FIFO is read only as far as its reader asks.

#include <cstddef>
#include <optional>
#include <string>

namespace kinestat::io {

/// An open, read-only file; closed when destroyed.
class ReadOnlyFile {
 public:
  /// Opens `path`. Throws InputError naming the file when it cannot be opened or examined, and
  /// with `folder_message` when it is a folder.
  ReadOnlyFile(const std::string& path, const char* folder_message);
  ~ReadOnlyFile();
  ReadOnlyFile(const ReadOnlyFile&) = delete;
  ReadOnlyFile& operator=(const ReadOnlyFile&) = delete;

  /// The size in bytes of a regular file; none for a device, FIFO or pipe (they have no size).
  std::optional<std::size_t> regular_size() const { return regular_size_; }

  /// Reads at most `bytes` bytes into `buffer` and returns how many, 0 at the end of the file.
  /// Retried when a signal interrupts it; throws InputError naming the file when reading fails.
  std::size_t read_some(char* buffer, std::size_t bytes);

 private:
  std::string path_;
  int descriptor_;
  std::optional<std::size_t> regular_size_;
};

}  // namespace kinestat::io
