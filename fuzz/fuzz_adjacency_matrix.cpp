// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer harness: any bytes as a whitespace adjacency matrix on standard input
// (`kinestat structure -`), through the reader and, for small mechanisms, the decomposition.
#include <cstddef>
#include <cstdint>
#include <string>

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/structure_reader.hpp"
#include "kinestat/structure/decomposition.hpp"
#include "kinestat/structure/transformations.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > (1 << 16)) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto model = kinestat::io::read_adjacency_text(text, "<stdin>");
    if (model.body_count() <= 64) {
      (void)kinestat::structure::analyse_structure(model);
      (void)kinestat::structure::structural_transformations(model, 64);
    }
  } catch (const kinestat::io::InputError&) {
  }
  return 0;
}
