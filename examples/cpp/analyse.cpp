// SPDX-License-Identifier: BSD-3-Clause
// A program using the installed kinestat package: reads a model file, analyses it, prints the verdict's numbers.
#include <iostream>
#include <kinestat/kinestat.hpp>

int main(int argc, char** argv) try {
  const kinestat::io::ModelFile file = kinestat::io::read_model_file(argc > 1 ? argv[1] : "model.yaml");
  if (file.network) {
    const kinestat::network::NetworkResult result = kinestat::io::analyse_network_file(*file.network, file.path);
    std::cout << result.model_name << ": FN = " << result.FN << ", CN = " << result.CN << '\n';
  } else if (file.framework) {
    const kinestat::framework::FrameworkResult result = kinestat::framework::analyse_framework(*file.framework);
    std::cout << file.framework->name << ": modes = " << result.mechanisms << ", self-stresses = " << result.self_stresses << '\n';
  }
} catch (const kinestat::Error& error) {  // every error kinestat throws: message, exit code, position
  std::cerr << error.what() << '\n';
  return error.exit_code();
}
