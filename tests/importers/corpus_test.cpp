// SPDX-License-Identifier: BSD-3-Clause
// Issue 37: public model files read as published (tests/importers/corpus/, README.md there names
// each file's repository, commit and licence). Each row of corpus/expected.tsv gives the counts
// derived without kinestat (count_joints.py for the trees, by hand for the loops, README.md);
// every file must give them through the library as the command reads it.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "kinestat/framework/framework_analysis.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/mjcf_reader.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/io/sdformat_reader.hpp"
#include "kinestat/io/urdf_reader.hpp"
#include "kinestat/network/analyse_network.hpp"

namespace kinestat::io::corpus_test {
namespace {

struct Row {
  std::string path, base;
  long fn = 0, cn = 0;
};

const std::string corpus = std::string(KINESTAT_SOURCE_DIR) + "/tests/importers/corpus/";

std::vector<Row> rows() {
  std::ifstream in(corpus + "expected.tsv");
  std::vector<Row> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    Row row;
    std::string fn, cn;
    std::getline(fields, row.path, '\t');
    std::getline(fields, fn, '\t');
    std::getline(fields, cn, '\t');
    std::getline(fields, row.base, '\t');
    row.fn = std::stol(fn);
    row.cn = std::stol(cn);
    out.push_back(row);
  }
  return out;
}

bool built_in(const std::string& path) {
  if (path.ends_with(".urdf")) return urdf_reader_built_in();
  if (path.ends_with(".sdf")) return sdformat_reader_built_in();
  if (path.ends_with(".xml")) return mjcf_reader_built_in();
  return true;
}

TEST(RealFilesCorpus, EveryFileGivesItsIndependentCount) {
  const std::vector<Row> table = rows();
  ASSERT_GE(table.size(), 40u) << "corpus/expected.tsv not read";
  for (const Row& row : table) {
    SCOPED_TRACE(row.path + (row.base == "-" ? "" : " --base " + row.base));
    if (!built_in(row.path)) continue;
    ImportOptions options;
    if (row.base == "fixed") options.base = ImportOptions::Base::fixed;
    if (row.base == "floating") options.base = ImportOptions::Base::floating;
    const ModelFile file = read_model_file(corpus + row.path, options);
    if (file.framework) {
      const framework::FrameworkResult r = framework::analyse_framework(*file.framework);
      EXPECT_EQ(r.mechanisms, row.fn);
      EXPECT_EQ(r.self_stresses, row.cn);
    } else {
      ASSERT_TRUE(file.network);
      const network::NetworkResult r = network::analyse_network(file.network->model);
      EXPECT_EQ(r.FN, row.fn);
      EXPECT_EQ(r.CN, row.cn);
    }
  }
}

// At least 30 distinct public files (a file read with two --base choices counts once).
TEST(RealFilesCorpus, HoldsAtLeastThirtyFiles) {
  std::vector<std::string> paths;
  for (const Row& row : rows())
    if (std::find(paths.begin(), paths.end(), row.path) == paths.end()) paths.push_back(row.path);
  EXPECT_GE(paths.size(), 30u);
}

// Every import says what it assumed: units and base (URDF), and which link floats.
TEST(RealFilesCorpus, ImportsSayWhatTheyAssumed) {
  if (!urdf_reader_built_in() || !sdformat_reader_built_in()) GTEST_SKIP();
  const auto joined = [](const std::vector<std::string>& notices) {
    std::string all;
    for (const auto& n : notices) all += n + "\n";
    return all;
  };
  const std::string urdf = joined(read_model_file(corpus + "urdf_tutorial/07-physics.urdf").notices);
  EXPECT_NE(urdf.find("lengths in metres; joint limits"), std::string::npos) << urdf;
  EXPECT_NE(urdf.find("base: the root link 'base_link' is the ground"), std::string::npos) << urdf;
  ImportOptions floating;
  floating.base = ImportOptions::Base::floating;
  const std::string floated = joined(read_model_file(corpus + "urdf_tutorial/07-physics.urdf", floating).notices);
  EXPECT_NE(floated.find("base: the root link 'base_link' floats"), std::string::npos) << floated;
  const std::string loose = joined(read_model_file(corpus + "sdformat/ball_prismatic_joint.sdf").notices);
  EXPECT_NE(loose.find("1 link(s) or group(s) of links joined to nothing else ('link3') float"), std::string::npos) << loose;
}

// The rigid catheter's RBEAM (issue 37) read as a rigid link: RLSE of an RBEAM is refused at
// its card (a rigid beam has no deformation), and an element SPACAR's public texts do not
// describe is still refused with what to write instead.
TEST(RealFilesCorpus, RbeamReleaseAndUndescribedElementsAreRefusedWhereWritten) {
  const auto refusal = [](const std::string& text) {
    const auto path = std::filesystem::temp_directory_path() / "kinestat_corpus_rbeam.dat";
    std::ofstream(path) << text;
    std::string message;
    try {
      (void)read_model_file(path.string());
    } catch (const InputError& error) {
      message = error.what();
    }
    std::filesystem::remove(path);
    return message;
  };
  const std::string head = "X 1 0 0 0\nX 3 1 0 0\nRBEAM 1 1 2 3 0 1 0\n";
  const std::string released = refusal(head + "RLSE 1 1\nEND\n");
  EXPECT_NE(released.find(":4:1: error: RLSE of RBEAM 1: a rigid beam has no deformation"), std::string::npos) << released;
  const std::string cylinder = refusal(head + "CYLINDER 2 1 2 3 0 1 0\nEND\n");
  EXPECT_NE(cylinder.find(":4:1: error: unsupported SPACAR keyword 'CYLINDER'"), std::string::npos) << cylinder;
  EXPECT_NE(cylinder.find("write the part with BEAM, TRUSS, HINGE and PINBODY elements"), std::string::npos) << cylinder;
}

// libsdformat's "The norm of the xyz vector cannot be zero" carries no line: it is placed at the
// first <xyz> of three zeros (line 4 here), as sdformat's own test model joint_axis_xyz_normalization.sdf.
TEST(RealFilesCorpus, ZeroAxisIsLocated) {
  if (!sdformat_reader_built_in()) GTEST_SKIP();
  const std::string text =
      "<sdf version='1.9'><model name='m'><link name='a'/><link name='b'/>\n"
      "<joint name='j' type='revolute'><parent>a</parent><child>b</child>\n<axis>\n"
      "<xyz>0 0 0</xyz>\n</axis></joint></model></sdf>\n";
  std::string message;
  try {
    (void)parse_sdformat("zero.sdf", text);
  } catch (const InputError& error) {
    message = error.what();
  }
  EXPECT_NE(message.find("zero.sdf:4:1: error: libsdformat: The norm of the xyz vector cannot be zero"), std::string::npos)
      << message;
}

// A URDF with two roots: the second is a loose link. Hand count: default, it floats (FN 6);
// --base fixed welds it (FN 0, CN 0: one rigid coupling, no loop); --base floating lets both
// float (FN 12).
TEST(RealFilesCorpus, LooseUrdfLinkFloatsUnlessFixedIsAsked) {
  if (!urdf_reader_built_in()) GTEST_SKIP();
  const std::string text = "<robot name='r'>\n <link name='a'/>\n <link name='b'/>\n</robot>\n";
  const auto counts = [&](ImportOptions::Base base) {
    ImportOptions options;
    options.base = base;
    const network::NetworkResult r = network::analyse_network(parse_urdf("two.urdf", text, options).loaded.model);
    return std::pair{r.FN, r.CN};
  };
  EXPECT_EQ(counts(ImportOptions::Base::format_default), std::pair(6, 0));
  EXPECT_EQ(counts(ImportOptions::Base::fixed), std::pair(0, 0));
  EXPECT_EQ(counts(ImportOptions::Base::floating), std::pair(12, 0));
}

}  // namespace
}  // namespace kinestat::io::corpus_test
