#pragma once
// Loads shipped example models for the network tests.

#include <string>

#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/yaml_support.hpp"

namespace kinestat::testing {

inline io::LoadedNetwork load_example(const std::string& name) {
  return io::read_network_model(io::YamlFile::load(std::string(KINESTAT_SOURCE_DIR) + "/examples/" + name));
}

inline io::LoadedNetwork parse_network(const std::string& text) {
  return io::read_network_model(io::YamlFile::parse("test.yaml", text));
}

}  // namespace kinestat::testing
