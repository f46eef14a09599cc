// SPDX-License-Identifier: BSD-3-Clause
// A program using the installed kinestat package: reads a model file of any kind, analyses it as
// `kinestat analyze` does (pipeline::analyse_model) and prints the counts and the verdict.
#include <iostream>
#include <kinestat/kinestat.hpp>

int main(int argc, char** argv) try {
  const kinestat::io::ModelFile file = kinestat::io::read_model_file(argc > 1 ? argv[1] : "model.yaml");
  const kinestat::pipeline::ModelAnalysis analysis = kinestat::pipeline::analyse_model(file);
  if (analysis.network) {
    const kinestat::network::NetworkResult& result = analysis.network->result;
    std::cout << result.model_name << ": FN = " << result.FN << ", CN = " << result.CN << '\n';
  } else if (analysis.sparse_network) {
    const kinestat::network::SparseNetworkResult& result = analysis.sparse_network->result;
    std::cout << file.path << ": FN = " << result.FN << ", CN = " << result.CN << '\n';
  } else if (analysis.framework) {
    const kinestat::framework::FrameworkResult& result = analysis.framework->result;
    std::cout << file.framework->name << ": modes = " << result.mechanisms << ", self-stresses = " << result.self_stresses
              << '\n';
  }
  // The verdict every report leads with, for every kind (structures too).
  std::cout << "verdict: " << analysis.verdict().summary << '\n';
} catch (const kinestat::Error& error) {  // every error kinestat throws: message, exit code, position
  std::cerr << error.what() << '\n';
  return error.exit_code();
}
