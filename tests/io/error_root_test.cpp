// SPDX-License-Identifier: BSD-3-Clause
// One error root (issue 14): every error the library throws on purpose is a kinestat::Error
// with the exit code a command ends with and, for input, the file position.
#include <gtest/gtest.h>

#include "kinestat/error.hpp"
#include "kinestat/graph/coupling_graph.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/linalg/homogeneous_solution.hpp"
#include "kinestat/network/analyse_network.hpp"
#include "kinestat/screw/coupling_basis.hpp"
#include "kinestat/structure/structure_model.hpp"

namespace kinestat {
namespace {

template <class Thrower>
Error caught(Thrower thrower) {
  try {
    thrower();
  } catch (const Error& error) {
    return error;
  }
  ADD_FAILURE() << "nothing thrown";
  return Error("nothing");
}

TEST(ErrorRoot, EveryLayerThrowsAKinestatErrorWithExitCodeTwo) {
  // Layer by layer, one way each fails on bad input.
  const Error graph = caught([] { graph::CouplingGraph({2, {{0, 1}, {0, 1}}}).tree_with_chords({}); });
  const Error geometry = caught([] {
    screw::CouplingGeometry g;
    g.axis = screw::Vec3{0, 0, 0};  // a revolute about no direction
    screw::coupling_basis(screw::CouplingType::revolute, g, screw::ScrewSpace::spatial());
  });
  const Error structure = caught([] { structure::model_from_couplings({"0", "1"}, {{1, 1, structure::PairKind::lower, 0, {}}}); });
  const Error model = caught([] { network::analyse_network(network::Model{}); });
  for (const Error* e : {&graph, &geometry, &structure, &model}) {
    EXPECT_EQ(e->exit_code(), kExitBadInput) << e->what();
    EXPECT_TRUE(e->where().file.empty()) << e->what();
  }
  EXPECT_NE(std::string(model.what()).find("no couplings"), std::string::npos) << model.what();
}

TEST(ErrorRoot, InputErrorsCarryTheirPosition) {
  const Error input = caught([] { io::parse_model_text("broken.yaml", "kind: network\nbodies: [a, b\n"); });
  EXPECT_EQ(input.exit_code(), 2);
  EXPECT_EQ(input.where().file, "broken.yaml");
  EXPECT_GE(input.where().line, 2);
  EXPECT_GE(input.where().column, 1);
  EXPECT_EQ(std::string(input.what()).rfind("broken.yaml:", 0), 0u) << input.what();
}

}  // namespace
}  // namespace kinestat
