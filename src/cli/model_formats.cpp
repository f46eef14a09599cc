// SPDX-License-Identifier: BSD-3-Clause
// The readers of other programs' formats as the commands use them: io::read_model_file picks
// the reader by the file's format (io::model_format), and the commands print its notices to
// standard error.

#include <iostream>

#include "cli/commands.hpp"
#include "cli/input_size_option.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/io/printable_text.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace kinestat::cli {

namespace {

// The command's import settings, set by its options before any model is read (the CLI is the
// one place for settings of the whole process; the library takes them as options).
io::ImportOptions& import_options() {
  static io::ImportOptions options;
  return options;
}

io::ModelFile read_with_notices(const std::string& path) {
  io::ImportOptions options = import_options();
  options.max_input_bytes = model_reading_limits().max_bytes;  // --max-input-size
  io::ModelFile file = io::read_model_file(path, options);
  print_notices(file.notices);
  return file;
}

}  // namespace

const std::vector<std::string>& print_notices(const std::vector<std::string>& notices) {
  for (const std::string& notice : notices) std::cerr << io::printable_text(notice) << '\n';
  return notices;
}

void add_import_options(CLI::App& command) {
  command.add_flag("--allow-outside-includes", import_options().allow_includes_outside_folder,
                   "SDFormat and MJCF: also read included files outside the model's folder (never the working directory's "
                   "or system folders unless named)");
  command
      .add_option_function<std::string>(
          "--base",
          [](const std::string& base) {
            import_options().base = base == "fixed" ? io::ImportOptions::Base::fixed : io::ImportOptions::Base::floating;
          },
          "URDF and SDFormat: the robot's base (URDF root link, SDFormat model without a joint to the world) is the ground "
          "(fixed, the default) or floats (floating, as a legged or mobile robot, and a model in Gazebo); a link joined to "
          "nothing else floats unless fixed is given (docs/formats.md)")
      ->check(CLI::IsMember({"fixed", "floating"}));
  add_input_size_option(command);
}

io::ModelFile read_model(const std::string& path) { return read_with_notices(path); }

framework::FrameworkModel read_spacar_model(const std::string& path) { return std::move(*read_with_notices(path).framework); }

io::LoadedNetwork read_imported_network(const std::string& path) { return std::move(*read_with_notices(path).network); }

}  // namespace kinestat::cli
