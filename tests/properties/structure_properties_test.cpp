// SPDX-License-Identifier: BSD-3-Clause
// Property-based tests of the structural-group decomposition (seed 004): the groups, their
// Eq. 1 parameters, the order relation between them, the DOF assignments and the part that
// cannot be decomposed depend on the mechanism, not on how it is written down. Each model is
// analysed again after renaming every body, renumbering the moving bodies at random,
// shuffling the pair list and swapping the two ends of pairs; the results are compared by
// body name. The frame stays first: the paper's body 1 is the frame by definition.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <sstream>

#include "kinestat/io/network_reader.hpp"
#include "kinestat/io/network_structure.hpp"
#include "kinestat/io/structure_reader.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "kinestat/structure/constraint_blocks.hpp"
#include "kinestat/structure/decomposition.hpp"
#include "support/mechanism_generator.hpp"

namespace kinestat::structure {
namespace {

using Names = std::set<std::string>;

Names names_of(const StructureModel& model, const std::vector<int>& bodies, const std::string& strip) {
  Names out;
  for (int b : bodies) out.insert(body_label(model, b).substr(strip.size()));
  return out;
}

// What a user reads off a decomposition, with bodies by name and groups by their bodies, so
// that it does not depend on body numbers or on the order in which groups were formed when
// two groups could be formed in either order.
//
// Where the mechanism is not well constrained only part of it is canonical: the
// over-constrained part, the under-constrained part, the counts of redundant constraints and
// missing inputs, and the groups that do not hang on the over-constrained part. Which bodies
// of the over-constrained part Eq. 1 still places follows the seed's visiting order (the body
// numbers), so those groups, the blocked bodies and the assignments are compared only when
// the decomposition is complete.
struct Canonical {
  bool complete = false;
  std::map<Names, std::vector<int>> groups;     // bodies -> {Nm, nc, P, Sc, stage}
  std::map<Names, std::set<Names>> after;       // bodies -> the groups it receives DOF from
  std::multiset<std::string> assignments;       // "receiver<-assigner:value"
  Names over_part, under, blocked;
  int redundant = 0, missing = 0, mobility = 0, inputs = 0;
  bool operator==(const Canonical&) const = default;
};

std::string describe(const Canonical& c) {
  std::ostringstream out;
  for (const auto& [bodies, p] : c.groups) {
    out << "{";
    for (const auto& b : bodies) out << b << " ";
    out << "} Nm " << p[0] << " nc " << p[1] << " P " << p[2] << " Sc " << p[3] << " stage " << p[4] << "\n";
  }
  out << "over part " << c.over_part.size() << " (+" << c.redundant << ") under " << c.under.size() << " (-"
      << c.missing << ") blocked " << c.blocked.size() << " mobility " << c.mobility;
  return out.str();
}

Canonical canonical(const StructureModel& model, const std::string& strip = "") {
  const StructureResult d = analyse_structure(model);
  const ConstraintBlocks blocks = find_constraint_blocks(model);
  Canonical c;
  c.complete = d.complete();
  // Bodies whose placement cannot depend on the visiting order: all of them when the
  // decomposition is complete, else the well-constrained blocks that need no
  // over-constrained body.
  std::vector<char> clean(static_cast<std::size_t>(model.body_count()), c.complete);
  for (std::size_t k = 0; k < blocks.blocks.size(); ++k)
    for (int b : blocks.blocks[k]) clean[static_cast<std::size_t>(b)] = c.complete || !blocks.needs_over_constrained[k];
  std::vector<Names> group_names{{body_label(model, 0).substr(strip.size())}};  // group 0: the frame
  for (const auto& g : d.groups) group_names.push_back(names_of(model, g.bodies, strip));
  for (const auto& g : d.groups) {
    if (!clean[static_cast<std::size_t>(g.bodies.front())]) continue;
    const Names& key = group_names[static_cast<std::size_t>(g.number)];
    c.groups[key] = {g.Nm, g.nc, g.P, g.Sc, g.stage};
    for (int before : g.after) c.after[key].insert(group_names[static_cast<std::size_t>(before)]);
  }
  if (c.complete) {
    for (const auto& a : d.assignments)
      c.assignments.insert(body_label(model, a.receiver).substr(strip.size()) + "<-" +
                           body_label(model, a.assigner).substr(strip.size()) + ":" + std::to_string(a.value));
    c.blocked = names_of(model, d.undecomposed.blocked, strip);
  }
  c.over_part = names_of(model, blocks.over_constrained, strip);
  // The decomposition reports the whole over-constrained part whenever part of it is left.
  if (!d.undecomposed.over_constrained.empty()) {
    EXPECT_EQ(d.undecomposed.over_constrained_part, blocks.over_constrained);
  }
  c.under = names_of(model, d.undecomposed.under_constrained, strip);
  c.redundant = blocks.redundant_units;
  c.missing = d.undecomposed.missing;
  c.mobility = model.mobility();
  c.inputs = model.input_count();
  return c;
}

// The same mechanism written down differently: bodies renamed with a prefix and renumbered
// (frame kept first), pairs in another order, some with their ends swapped.
StructureModel rewritten(const StructureModel& model, std::mt19937& rng, const std::string& prefix) {
  const int n = model.body_count();
  std::vector<int> new_index(static_cast<std::size_t>(n));
  std::iota(new_index.begin(), new_index.end(), 0);
  std::shuffle(new_index.begin() + 1, new_index.end(), rng);
  StructureModel out;
  out.name = model.name;
  out.dimension = model.dimension;
  out.body_names.resize(static_cast<std::size_t>(n));
  for (int b = 0; b < n; ++b) out.body_names[static_cast<std::size_t>(new_index[static_cast<std::size_t>(b)])] = prefix + body_label(model, b);
  for (Pair p : model.pairs) {
    p.a = new_index[static_cast<std::size_t>(p.a)];
    p.b = new_index[static_cast<std::size_t>(p.b)];
    if (rng() % 2) std::swap(p.a, p.b);
    out.pairs.push_back(p);
  }
  std::shuffle(out.pairs.begin(), out.pairs.end(), rng);
  return out;
}

// Checks the invariance for `rewrites` rewritings; returns how many were compared.
int check_invariance(const StructureModel& model, std::mt19937& rng, const std::string& what, int rewrites = 3) {
  const Canonical original = canonical(model);
  for (int k = 0; k < rewrites; ++k) {
    const std::string prefix = "renamed" + std::to_string(k) + "_";
    const Canonical again = canonical(rewritten(model, rng, prefix), prefix);
    EXPECT_TRUE(again == original) << what << ", rewrite " << k << "\noriginal:\n"
                                   << describe(original) << "\nrewritten:\n"
                                   << describe(again);
  }
  return rewrites;
}

// Every shipped model a structural analysis reads: structure files, and network files with
// inputs (their couplings give the pairs).
std::vector<std::pair<std::string, StructureModel>> shipped_models() {
  std::vector<std::pair<std::string, StructureModel>> out;
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(KINESTAT_SOURCE_DIR) + "/examples"))
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const auto& path : files) {
    const auto file = io::YamlFile::load(path.string());
    const std::string kind = io::model_kind(file);
    if (kind == "structure") {
      out.emplace_back(path.filename().string(), io::read_structure_model(file));
    } else if (kind == "network") {
      const auto loaded = io::read_network_model(file);
      if (loaded.model.inputs.empty()) continue;
      out.emplace_back(path.filename().string(), io::structure_of_network(loaded, path.string()));
    }
  }
  return out;
}

TEST(StructureProperties, EveryShippedModelUnderRenamingAndReordering) {
  std::mt19937 rng(11);
  const auto models = shipped_models();
  ASSERT_GE(models.size(), 11u);  // the structure files, and network files with inputs
  for (const auto& [name, model] : models) check_invariance(model, rng, name, 8);
}

TEST(StructureProperties, GeneratedMechanismsUnderRenamingAndReordering) {
  std::mt19937 rng(12);
  for (std::uint32_t seed = 1; seed <= 80; ++seed) {
    const GeneratedMechanism g = generate_group_chain(4 + static_cast<int>(seed % 40), seed, {}, seed % 2 == 0);
    check_invariance(g.model, rng, "generated chain " + std::to_string(seed));
  }
  for (int rungs : {2, 3, 5}) check_invariance(generate_ladder_group(rungs).model, rng, "ladder");
  for (int ring : {4, 6, 10}) check_invariance(generate_ring_group(ring).model, rng, "ring");
}

// Random adjacency matrices are mostly not well constrained: this exercises the invariance of
// the undecomposed part (over- and under-constrained and blocked bodies) as well.
TEST(StructureProperties, RandomAdjacencyMatricesUnderRenamingAndReordering) {
  std::mt19937 rng(13);
  int complete = 0, incomplete = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    const int n = 3 + static_cast<int>(rng() % 8);
    std::vector<std::vector<int>> m(static_cast<std::size_t>(n), std::vector<int>(static_cast<std::size_t>(n), 0));
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if (rng() % 3 == 0) m[i][j] = m[j][i] = 1 + static_cast<int>(rng() % 5);
    const StructureModel model = model_from_adjacency(m);
    (analyse_structure(model).complete() ? complete : incomplete)++;
    check_invariance(model, rng, "random matrix " + std::to_string(trial), 2);
  }
  // Both outcomes must be exercised for the test to mean something.
  EXPECT_GT(complete, 20);
  EXPECT_GT(incomplete, 20);
}

// The same through the file reader: a shipped adjacency matrix with its bodies renumbered
// (rows and columns permuted) and renamed reads to the same decomposition.
TEST(StructureProperties, PermutedAdjacencyFileReadsToTheSameGroups) {
  const auto file = io::YamlFile::load(std::string(KINESTAT_SOURCE_DIR) + "/examples/saura-eq3.yaml");
  const StructureModel model = io::read_structure_model(file);
  const auto adjacency = adjacency_of(model);
  ASSERT_FALSE(adjacency.empty());
  const int n = model.body_count();
  std::mt19937 rng(14);
  for (int k = 0; k < 5; ++k) {
    std::vector<int> order(static_cast<std::size_t>(n));  // order[new] = old
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin() + 1, order.end(), rng);
    std::ostringstream text;
    text << "kinestat: 1\nkind: structure\nbodies: [";
    for (int i = 0; i < n; ++i) text << (i ? ", " : "") << "x_" << body_label(model, order[static_cast<std::size_t>(i)]);
    text << "]\nadjacency:\n";
    for (int i = 0; i < n; ++i) {
      text << "  - [";
      for (int j = 0; j < n; ++j)
        text << (j ? ", " : "") << adjacency[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])][static_cast<std::size_t>(order[static_cast<std::size_t>(j)])];
      text << "]\n";
    }
    const StructureModel permuted = io::read_structure_model(io::YamlFile::parse("permuted.yaml", text.str()));
    EXPECT_TRUE(canonical(permuted, "x_") == canonical(model)) << text.str();
  }
}

}  // namespace
}  // namespace kinestat::structure
