// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer harness for semantic fuzzing (issue 40): the bytes steer a generator of valid model
// files (tests/support/valid_models.hpp: every kind, with the degenerate cases weighted in), and
// every generated model is read, analysed, judged and reported. Besides crashes, hangs and
// sanitizer reports, a broken counting identity (Maxwell's rule, Davies's FN/CN identities),
// dense and sparse ranks that differ, or a framework proposal that does not leave D(c) square
// and non-singular is a finding: the harness aborts with the model file and what failed.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "support/valid_models.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  kinestat::testing::ByteChoices choices(data, size);
  const std::string text = kinestat::testing::random_model_yaml(choices);
  const kinestat::testing::ModelCheck check = kinestat::testing::check_model_text(text);
  if (!check.failed.empty()) {
    std::fprintf(stderr, "property failed: %s\nmodel:\n%s\n", check.failed.c_str(), text.c_str());
    std::abort();
  }
  return 0;
}
