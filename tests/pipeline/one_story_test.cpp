// SPDX-License-Identifier: BSD-3-Clause
// Issue 35 item 6: `analyze` and `structure` on the same network file give the same geometric
// verdict, and where the structural (generic) count the groups use differs, both say so with
// both numbers. The expected counts are derived by hand below, not from the program.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "kinestat/io/model_file.hpp"
#include "kinestat/pipeline/model_pipeline.hpp"
#include "support/cli_run.hpp"

namespace kinestat {
namespace {

using testing::example_path;
using testing::run_cli;

nlohmann::json verdict_of(const std::string& command, const std::string& example) {
  const auto run = run_cli(command + " --json " + example_path(example));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return nlohmann::json::parse(run.out).at("verdict");
}

// Bennett's linkage: n = 4 bodies, 4 revolutes (f = 1, c = 5 each), one circuit, d = 6.
// Grübler–Kutzbach: 6 (n − 1) − Σc = 18 − 20 = −2, so the structural (generic) count is
// FN = 0, CN = 2. The Bennett geometry (a / sin α = b / sin β) has one motion: FN = 1, and
// FN − CN = F − d l = 4 − 6 = −2 gives CN = 3 (Bennett 1903; Hunt 1978, §12.6).
TEST(OneStory, BennettSameGeometricVerdictWithGenericCountBeside) {
  const nlohmann::json analyze = verdict_of("analyze", "bennett.yaml");
  const nlohmann::json structure = verdict_of("structure", "bennett.yaml");
  EXPECT_EQ(analyze.at("summary"), structure.at("summary"));
  EXPECT_EQ(analyze.at("redundant_constraints"), 3);
  EXPECT_EQ(analyze.at("intended_motions"), 1);
  EXPECT_EQ(structure.at("redundant_constraints"), 3);
  EXPECT_EQ(structure.at("intended_motions"), 1);
  for (const nlohmann::json& v : {analyze, structure}) {
    EXPECT_EQ(v.at("geometric_counts"), (nlohmann::json{{"FN", 1}, {"CN", 3}}));
    EXPECT_EQ(v.at("generic_counts"), (nlohmann::json{{"FN", 0}, {"CN", 2}}));
  }
  // One line in each text report with both numbers.
  for (const char* command : {"analyze", "structure"}) {
    const auto run = run_cli(std::string(command) + " " + example_path("bennett.yaml"));
    EXPECT_NE(run.out.find("counts differ: FN = 1, CN = 3 from the geometry; FN = 0, CN = 2 by the structural (generic) count"),
              std::string::npos)
        << command << ":\n"
        << run.out;
  }
}

// The planar four-bar: n = 4, 4 revolutes (f = 1, c = 2 in the plane, d = 3). Grübler–Kutzbach:
// 3 (n − 1) − Σc = 9 − 8 = 1, and the geometry (no three pivots collinear) agrees: FN = 1,
// CN = FN − (F − d l) = 1 − (4 − 3) = 0. With no inputs declared the one motion is the intended
// one, for both commands; the counts agree, so neither says they differ.
TEST(OneStory, PlanarFourBarExactlyConstrainedInBothCommands) {
  const nlohmann::json analyze = verdict_of("analyze", "four-bar-planar.yaml");
  const nlohmann::json structure = verdict_of("structure", "four-bar-planar.yaml");
  for (const nlohmann::json& v : {analyze, structure}) {
    EXPECT_EQ(v.at("exactly_constrained"), true);
    EXPECT_EQ(v.at("intended_motions"), 1);
    EXPECT_EQ(v.at("extra_motions"), 0);
    EXPECT_FALSE(v.contains("geometric_counts"));
    EXPECT_FALSE(v.contains("generic_counts"));
  }
  EXPECT_EQ(analyze.at("summary"), structure.at("summary"));
}

// The structural count by itself (pipeline::structural_count), on the structure of Bennett's
// couplings: the hand count above.
TEST(OneStory, StructuralCountIsGrueblerKutzbach) {
  const io::ModelFile file = io::read_model_file(example_path("bennett.yaml"));
  const pipeline::ModelAnalysis analysis = pipeline::decompose_model(file);
  ASSERT_TRUE(analysis.structure);
  EXPECT_EQ(pipeline::structural_count(analysis.structure->model), (design::Counts{0, 2}));
  // The geometric answer the verdict carries: Bennett's one motion.
  ASSERT_TRUE(analysis.network);
  EXPECT_EQ(analysis.network->result.FN, 1);
  EXPECT_EQ(analysis.network->result.CN, 3);
}

}  // namespace
}  // namespace kinestat
