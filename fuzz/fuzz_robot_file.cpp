// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer harness: any bytes as a robot description (built three times, as fuzz_urdf_file,
// fuzz_sdformat_file and fuzz_mjcf_file, with KINESTAT_FUZZ_READ naming the reader), through
// the reader and, for small models, the network analysis and the YAML writer, whose output
// must read back. Input errors are expected; any other exception, crash, hang or sanitizer
// report is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/mjcf_reader.hpp"
#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/network_yaml_writer.hpp"
#include "kinestat/io/sdformat_reader.hpp"
#include "kinestat/io/urdf_reader.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/network/analyse_network.hpp"

namespace {
constexpr std::size_t kMaxInputBytes = 1 << 16;
constexpr std::size_t kMaxAnalysedCouplings = 16;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > kMaxInputBytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  kinestat::io::ImportedNetwork imported;
  try {
    imported = kinestat::io::KINESTAT_FUZZ_READ("fuzz.input", text);
  } catch (const kinestat::io::InputError&) {
    return 0;
  }
  const auto& model = imported.loaded.model;
  if (model.couplings.size() <= kMaxAnalysedCouplings) {
    try {
      (void)kinestat::network::analyse_network(model);
    } catch (const kinestat::network::ModelError&) {
      // e.g. a link joined to nothing: the command reports it at the file
    }
  }
  // What the reader accepted, the YAML writer must express and the YAML reader read back.
  try {
    (void)kinestat::io::read_network_model(kinestat::io::YamlFile::parse("again.yaml", kinestat::io::network_yaml(model)));
  } catch (const kinestat::io::InputError&) {
    std::abort();
  }
  return 0;
}
