// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Runs the built `kinestat` command for CLI tests and captures exit code, stdout and stderr.

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/scratch_folder.hpp"

namespace kinestat::testing {

struct CliRun {
  int exit_code = -1;
  std::string out, err;
};

/// Runs `kinestat <arguments>` (arguments are passed to the shell as written).
inline CliRun run_cli(const std::string& arguments, const std::string& standard_input = {}) {
  const auto& dir = scratch_folder();
  const std::string err_path = (dir / "kinestat_cli_stderr").string();
  std::string command = std::string(KINESTAT_CLI) + " " + arguments + " 2>" + err_path;
  std::string in_path;
  if (!standard_input.empty()) {
    in_path = (dir / "kinestat_cli_stdin").string();
    std::ofstream(in_path) << standard_input;
    command += " <" + in_path;
  }
  CliRun r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer{};
  std::size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) r.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(err_path);
  std::stringstream s;
  s << err.rdbuf();
  r.err = s.str();
  std::filesystem::remove(err_path);
  if (!in_path.empty()) std::filesystem::remove(in_path);
  return r;
}

/// Path of a shipped example.
inline std::string example_path(const std::string& name) { return std::string(KINESTAT_SOURCE_DIR) + "/examples/" + name; }

/// Writes `text` to a file of this name in the process's scratch folder and returns its path.
inline std::string write_temp_file(const std::string& name, const std::string& text) {
  const auto path = scratch_folder() / name;
  std::ofstream(path) << text;
  return path.string();
}

}  // namespace kinestat::testing
