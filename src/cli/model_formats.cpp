// The readers of other programs' formats as the commands use them: io::read_model_file picks
// the reader by the file's format (io::model_format), and the commands print its notices to
// standard error.

#include <iostream>

#include "cli/commands.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/io/printable_text.hpp"

namespace kinestat::cli {

namespace {

io::ModelFile read_with_notices(const std::string& path) {
  io::ModelFile file = io::read_model_file(path);
  for (const std::string& notice : file.notices) std::cerr << io::printable_text(notice) << '\n';
  return file;
}

}  // namespace

framework::FrameworkModel read_spacar_model(const std::string& path) { return std::move(*read_with_notices(path).framework); }

io::LoadedNetwork read_imported_network(const std::string& path) { return std::move(*read_with_notices(path).network); }

}  // namespace kinestat::cli
