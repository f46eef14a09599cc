// SPDX-License-Identifier: BSD-3-Clause
// Issue 40 item 5: every importer and `sweep --merge` read through the bounded reader of YAML
// model files (64 MiB, devices and FIFOs read only up to the limit), and read in time linear in
// the number of joints: a chain of 2 * 10^4 revolutes (URDF) and of 2 * 10^4 trusses (SPACAR).

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>

#include "kinestat/address_sanitizer.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/mjcf_reader.hpp"
#include "kinestat/io/model_file.hpp"
#include "kinestat/io/sdformat_reader.hpp"
#include "kinestat/io/spacar_reader.hpp"
#include "kinestat/io/urdf_reader.hpp"
#include "kinestat/io/yaml_support.hpp"
#include "support/cli_run.hpp"

namespace kinestat::testing {
namespace {

// The time bounds tell linear from quadratic reading (> 16 s for the URDF chain when quadratic);
// under AddressSanitizer everything runs about four times slower (measured: the chain 15.8 s).
constexpr double kTimeScale = kinestat::kBuiltWithAddressSanitizer ? 4.0 : 1.0;

namespace fs = std::filesystem;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// One line naming the file and the limit, exit 2, nothing on standard output. An .xml file that
// is a device or a FIFO is refused at once, before it is read (io/model_format: its root element
// would be read first and the file opened again by its reader).
void expect_refused_at_the_limit(const CliRun& r, const std::string& path) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;  // one line
  EXPECT_TRUE(has(r.err, path)) << r.err;
  EXPECT_TRUE(has(r.err, path.ends_with(".xml") ? "an .xml model must be a regular file (this is a pipe or device)" : "64 MiB limit")) << r.err;
}

bool built_in(const CliRun& r) { return !has(r.err, "not built in"); }

// A link named like a model file that leads to /dev/zero: endless, no size.
TEST(BoundedReading, ZeroDeviceAsEveryFormatIsRefusedAtTheLimit) {
  for (const char* extension : {"urdf", "sdf", "dat", "xml"}) {
    const fs::path link = scratch_folder() / (std::string("zero.") + extension);
    fs::remove(link);
    fs::create_symlink("/dev/zero", link);
    const auto start = std::chrono::steady_clock::now();
    const CliRun r = run_cli("analyze " + link.string());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!built_in(r)) continue;
    SCOPED_TRACE(extension);
    expect_refused_at_the_limit(r, link.string());
    EXPECT_LT(seconds, 20.0 * kTimeScale);  // 64 MiB read and dropped, not memory filled
  }
  const fs::path link = scratch_folder() / "zero.jsonl";
  fs::remove(link);
  fs::create_symlink("/dev/zero", link);
  expect_refused_at_the_limit(run_cli("sweep --merge " + link.string()), link.string());
}

// An endless FIFO given as a model file of each format, and to `sweep --merge`.
TEST(BoundedReading, EndlessFifoAsEveryFormatIsRefusedAtTheLimit) {
  std::signal(SIGPIPE, SIG_IGN);
  for (const char* extension : {"urdf", "sdf", "dat", "xml", "jsonl"}) {
    const fs::path fifo = scratch_folder() / (std::string("endless.") + extension);
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::thread writer([&] {
      const int fd = ::open(fifo.c_str(), O_WRONLY);
      const std::string block(1 << 16, '<');
      while (fd >= 0 && ::write(fd, block.data(), block.size()) > 0) {
      }
      if (fd >= 0) ::close(fd);
    });
    const bool merge = std::string(extension) == "jsonl";
    const CliRun r = run_cli((merge ? "sweep --merge " : "analyze ") + fifo.string());
    if (!built_in(r)) {
      // The reader was never opened: open and close it so that the writer ends.
      const int fd = ::open(fifo.c_str(), O_RDONLY);
      if (fd >= 0) ::close(fd);
    }
    writer.join();
    if (!built_in(r)) continue;
    SCOPED_TRACE(extension);
    expect_refused_at_the_limit(r, fifo.string());
  }
}

// A serial chain of n revolutes: n + 1 links, n joints. Counting by hand: FN = n (one rotation
// a joint, an open chain), CN = 0.
std::string urdf_chain(int n) {
  std::string text = "<robot name=\"chain\">\n";
  for (int i = 0; i <= n; ++i) text += "  <link name=\"l" + std::to_string(i) + "\"/>\n";
  for (int i = 0; i < n; ++i)
    text += "  <joint name=\"j" + std::to_string(i) + "\" type=\"revolute\"><parent link=\"l" + std::to_string(i) +
            "\"/><child link=\"l" + std::to_string(i + 1) + "\"/><origin xyz=\"1 0 0\"/><axis xyz=\"0 0 1\"/></joint>\n";
  return text + "</robot>\n";
}

TEST(BoundedReading, UrdfChainReadsInLinearTime) {
  if (!io::urdf_reader_built_in()) GTEST_SKIP();
  constexpr int n = 20000;
  const std::string text = urdf_chain(n);
  const auto start = std::chrono::steady_clock::now();
  const io::ImportedNetwork imported = io::parse_urdf("chain.urdf", text);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(imported.loaded.model.couplings.size(), std::size_t{n});
  EXPECT_EQ(imported.loaded.model.bodies.size(), std::size_t{n + 1});
  // Joint i sits at (i + 1, 0, 0): the frames were chained through every joint, the last at n.
  const auto& last = imported.loaded.model.couplings.back().geometry.point;
  EXPECT_EQ(last[0], screw::Rational(*io::parse_exact_decimal("20000")));
  EXPECT_EQ(last[1], screw::Rational(*io::parse_exact_decimal("0")));
  // Quadratic reading took > 400 s for 10^5 joints (issue 40), so > 16 s for 2 * 10^4; linear
  // reading takes well under a second here (measured 10^5: see docs/formats.md).
  EXPECT_LT(seconds, 8.0 * kTimeScale);
}

// A chain of trusses: n + 1 nodes, n trusses; duplicates of element numbers are still found.
TEST(BoundedReading, SpacarTrussChainReadsInLinearTime) {
  constexpr int n = 20000;
  std::string text;
  for (int i = 0; i <= n; ++i) text += "X " + std::to_string(i + 1) + " " + std::to_string(i) + " " + std::to_string(i % 2) + " 0\n";
  for (int i = 0; i < n; ++i) text += "TRUSS " + std::to_string(i + 1) + " " + std::to_string(i + 1) + " " + std::to_string(i + 2) + "\n";
  const auto start = std::chrono::steady_clock::now();
  const io::SpacarImport imported = io::parse_spacar("chain.dat", text + "END\n");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(imported.model.nodes.size(), std::size_t{n + 1});
  EXPECT_EQ(imported.model.elements.size(), std::size_t{n});
  EXPECT_LT(seconds, 8.0 * kTimeScale);
  try {
    (void)io::parse_spacar("chain.dat", text + "TRUSS 7 1 3\nEND\n");
    ADD_FAILURE() << "a duplicate element number was read";
  } catch (const io::InputError& error) {
    EXPECT_TRUE(has(error.what(), "chain.dat:" + std::to_string(2 * n + 2) + ":7: error: element 7 is defined twice (first on line " +
                                      std::to_string(n + 1 + 7) + ")"))
        << error.what();
  }
}

TEST(BoundedReading, DuplicateJointNamesAreFoundAmongManyJoints) {
  if (!io::urdf_reader_built_in()) GTEST_SKIP();
  std::string text = urdf_chain(3000);
  // A fourth-thousandth joint named like the first: line 1 + 3001 links + 3000 joints + 1.
  text.insert(text.rfind("</robot>"),
              "  <link name=\"extra\"/>\n  <joint name=\"j0\" type=\"fixed\"><parent link=\"l0\"/><child link=\"extra\"/></joint>\n");
  try {
    (void)io::parse_urdf("dup.urdf", text);
    ADD_FAILURE() << "a duplicate joint name was read";
  } catch (const io::InputError& error) {
    EXPECT_TRUE(has(error.what(), "dup.urdf:6004:3: error: duplicate joint name 'j0'")) << error.what();
  }
}

// libsdformat 12 and MuJoCo 2.2.2 are not linear in the model's size (docs/formats.md): models
// beyond their limits are refused at once, with the limit named, before the library starts.
TEST(BoundedReading, SdformatAndMjcfBeyondTheirLibrariesLimitsAreRefusedEarly) {
  if (io::sdformat_reader_built_in()) {
    // 1001 links and 1000 joints: 2001 elements, one past the limit of 2000.
    std::string text = "<sdf version=\"1.9\">\n<model name=\"chain\">\n";
    for (int i = 0; i <= 1000; ++i) text += "<link name=\"l" + std::to_string(i) + "\"/>\n";
    for (int i = 0; i < 1000; ++i)
      text += "<joint name=\"j" + std::to_string(i) + "\" type=\"revolute\"><parent>l" + std::to_string(i) + "</parent><child>l" +
              std::to_string(i + 1) + "</child><axis><xyz>0 0 1</xyz></axis></joint>\n";
    text += "</model>\n</sdf>\n";
    const auto start = std::chrono::steady_clock::now();
    try {
      (void)io::parse_sdformat("big.sdf", text);
      ADD_FAILURE() << "a model past the limit was read";
    } catch (const io::InputError& error) {
      EXPECT_TRUE(has(error.what(), "big.sdf:1:1: error: the file has 2001 <link> and <joint> elements; kinestat reads at most 2000"))
          << error.what();
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
  }
  if (io::mjcf_reader_built_in()) {
    std::string text = "<mujoco>\n<worldbody>\n";
    for (int i = 0; i < 10001; ++i) text += "<body name=\"b" + std::to_string(i) + "\"><joint type=\"hinge\"/><geom size=\"0.1\"/></body>\n";
    text += "</worldbody>\n</mujoco>\n";
    try {
      (void)io::parse_mjcf("big.xml", text);
      ADD_FAILURE() << "a model past the limit was read";
    } catch (const io::InputError& error) {
      EXPECT_TRUE(has(error.what(), "big.xml: error: the model has 10001 <body> elements; kinestat reads at most 10000")) << error.what();
    }
  }
}

}  // namespace
}  // namespace kinestat::testing
