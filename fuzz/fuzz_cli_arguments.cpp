// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer harness: the command line. The input is split at newlines into arguments; the
// argument "model.yaml" names a valid model in a scratch folder, so the fuzzer explores options
// around real input. Inputs with '/' in an argument or an output option are skipped, so that
// nothing outside the scratch folder is read and nothing is written.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include "cli/commands.hpp"

namespace {

// The scratch folder of this process, removed when the fuzzer exits.
struct ScratchFolder {
  std::filesystem::path path = std::filesystem::temp_directory_path() / ("kinestat-fuzz-cli-" + std::to_string(::getpid()));
  ScratchFolder() { std::filesystem::create_directories(path); }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

const std::string& scratch_model() {
  static const ScratchFolder folder;
  static const std::string path = [] {
    const auto model = folder.path / "model.yaml";
    std::ofstream(model) << "kinestat: 1\nname: fuzz\ncouplings:\n"
                            "  - {name: A, type: spherical, between: [1, 2]}\n"
                            "  - {name: B, type: spherical, between: [1, 2], point: [0, 0, 1]}\n";
    return model.string();
  }();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return 0;
  std::vector<std::string> arguments{"kinestat"};
  std::string current;
  for (std::size_t i = 0; i < size; ++i) {
    const char ch = static_cast<char>(data[i]);
    if (ch == '\n') {
      arguments.push_back(current);
      current.clear();
    } else {
      current += ch;
    }
  }
  arguments.push_back(current);
  std::vector<const char*> argv;
  for (auto& argument : arguments) {
    if (argument.find('/') != std::string::npos || argument.find('\0') != std::string::npos) return 0;
    if (argument.rfind("-o", 0) == 0 || argument.rfind("--o", 0) == 0) return 0;
    if (argument == "model.yaml") argument = scratch_model();
  }
  for (const auto& argument : arguments) argv.push_back(argument.c_str());
  const int code = kinestat::cli::run(static_cast<int>(argv.size()), argv.data());
  // 1 = `sweep` wrote every line but some variants failed (docs/sweep.md); 3 = internal error: a bug.
  if (code != 0 && code != 2 && !(code == 1 && arguments.size() > 1 && arguments[1] == "sweep")) __builtin_trap();
  return 0;
}
