// libFuzzer harness: any bytes as a model file (network, framework or structure), through the
// reader of its kind and, for small models, the analyses. Input errors are expected; any other exception, crash, hang or
// sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/framework_reader.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/network_structure.hpp"
#include "kinestat/io/structure_reader.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/structure/decomposition.hpp"
#include "kinestat/structure/transformations.hpp"

namespace {
// Large fuzzed models only cost time: the analysis is exercised on small ones.
constexpr std::size_t kMaxAnalysedCouplings = 16;
constexpr std::size_t kMaxAnalysedElements = 64;
constexpr int kMaxAnalysedBodies = 64;

void analyse_structure(const kinestat::structure::StructureModel& model) {
  if (model.body_count() > kMaxAnalysedBodies) return;
  (void)kinestat::structure::decompose(model);
  (void)kinestat::structure::structural_transformations(model, 64);
}
constexpr std::size_t kMaxInputBytes = 1 << 16;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > kMaxInputBytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto file = kinestat::io::YamlFile::parse("fuzz.yaml", text);
    const std::string kind = kinestat::io::model_kind(file);
    if (kind == "network") {
      const auto loaded = kinestat::io::read_network_model(file);
      if (loaded.model.couplings.size() <= kMaxAnalysedCouplings) {
        try {
          (void)kinestat::network::analyse_network(loaded.model);
        } catch (const kinestat::network::ModelError& error) {
          (void)kinestat::io::locate(error, loaded, file.path());
        }
        analyse_structure(kinestat::io::structure_of_network(loaded, file.path()));
      }
    } else if (kind == "framework") {
      const auto model = kinestat::io::read_framework(file);
      if (model.elements.size() <= kMaxAnalysedElements) (void)kinestat::framework::analyse_framework(model);
    } else if (kind == "structure") {
      analyse_structure(kinestat::io::read_structure_model(file));
    }
  } catch (const kinestat::io::InputError&) {
  }
  return 0;
}
