// SPDX-License-Identifier: BSD-3-Clause
// Issue 35, item 6: every kind declares its intended motions with the same key, `inputs:` (the
// old `independent:` of frameworks keeps working), and the verdict says what it took as intended
// and why.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "kinestat/io/model_file.hpp"
#include "kinestat/pipeline/model_pipeline.hpp"
#include "support/cli_run.hpp"

namespace kinestat {
namespace {

std::string example_text(const std::string& name) {
  std::ifstream in(testing::example_path(name));
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// The wire-flexure guide declares the platform's vertical translation C.z as its one intended
// motion (seed 002's straight guide): written `inputs:` it is the same model.
TEST(IntendedMotions, FrameworkInputsKeyIsIndependent) {
  const std::string text = example_text("wire-flexure-guide.yaml");
  const io::ModelFile seed_key = io::parse_model_text("guide.yaml", text);
  const io::ModelFile common_key = io::parse_model_text("guide.yaml", replaced(text, "independent: {C: [z]}", "inputs: {C: [z]}"));
  const pipeline::ModelAnalysis a = pipeline::analyse_model(seed_key), b = pipeline::analyse_model(common_key);
  EXPECT_EQ(a.verdict().intended_motions, 1);
  EXPECT_EQ(b.verdict().intended_motions, 1);
  EXPECT_EQ(pipeline::report_json_text(seed_key, a), pipeline::report_json_text(common_key, b));
  EXPECT_THROW(io::parse_model_text("guide.yaml", replaced(text, "independent: {C: [z]}",
                                                           "independent: {C: [z]}\ninputs: {C: [z]}")),
               io::InputError);
}

// No `inputs:` on a network: every motion but idle spins is intended (Bennett: its one motion),
// and the verdict says that none was declared.
TEST(IntendedMotions, VerdictSaysNoneDeclared) {
  const io::ModelFile bennett = io::read_model_file(testing::example_path("bennett.yaml"));
  const pipeline::ModelAnalysis bennett_analysis = pipeline::analyse_model(bennett);
  const design::Verdict& v = bennett_analysis.verdict();
  EXPECT_EQ(v.intended_motions, 1);
  EXPECT_EQ(v.intended_basis.rfind("none declared", 0), 0U) << v.intended_basis;
  // Seed 004's four-bar drives its crank (one input on the pair frame-crank): declared.
  const io::ModelFile four_bar = io::read_model_file(testing::example_path("saura-four-bar.yaml"));
  const pipeline::ModelAnalysis four_bar_analysis = pipeline::analyse_model(four_bar);
  const design::Verdict& w = four_bar_analysis.verdict();
  EXPECT_EQ(w.intended_motions, 1);
  EXPECT_EQ(w.intended_basis, "the declared 'inputs:' of the pairs");
}

}  // namespace
}  // namespace kinestat
