// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/read_only_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "kinestat/io/input_error.hpp"

namespace kinestat::io {

ReadOnlyFile::ReadOnlyFile(const std::string& path, const char* folder_message)
    : path_(path), descriptor_(::open(path.c_str(), O_RDONLY | O_CLOEXEC)) {
  if (descriptor_ < 0)
    throw InputError({path_, 0, 0}, fmt::format("cannot open file for reading: {}", std::strerror(errno)));
  struct stat info {};
  if (::fstat(descriptor_, &info) != 0) {
    const int error = errno;
    ::close(descriptor_);
    throw InputError({path_, 0, 0}, fmt::format("cannot read the model file: {}", std::strerror(error)));
  }
  if (S_ISDIR(info.st_mode)) {
    ::close(descriptor_);
    throw InputError({path_, 0, 0}, folder_message);
  }
  if (S_ISREG(info.st_mode)) regular_size_ = static_cast<std::size_t>(info.st_size);
}

ReadOnlyFile::~ReadOnlyFile() { ::close(descriptor_); }

std::size_t ReadOnlyFile::read_some(char* buffer, std::size_t bytes) {
  while (true) {
    const ssize_t got = ::read(descriptor_, buffer, bytes);
    if (got >= 0) return static_cast<std::size_t>(got);
    if (errno != EINTR)
      throw InputError({path_, 0, 0}, fmt::format("cannot read the model file: {}", std::strerror(errno)));
  }
}

}  // namespace kinestat::io
