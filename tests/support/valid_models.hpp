// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Random *valid* model files for semantic fuzzing and property tests (issue 40): byte fuzzing
// rarely writes a model the readers accept, so the crash of a framework whose every node is
// supported was never reached. These generators write small YAML models of every kind from a
// stream of choices, leaning on the degenerate cases: every node supported, no free coordinate,
// no element, one body, a body on one coupling, coincident and collinear nodes, zero-length
// bars (which the reader refuses), every coupling of one type. The choices come from fuzz bytes
// (libFuzzer steers them) or from a seeded generator (the property tests).

#include <cstddef>
#include <cstdint>
#include <random>
#include <string>

namespace kinestat::testing {

/// A source of small whole-number choices.
class Choices {
 public:
  virtual ~Choices() = default;
  /// A number in [lo, hi] (lo <= hi).
  virtual int pick(int lo, int hi) = 0;
};

/// Choices read from bytes, one byte a choice; lo once the bytes are used up, so every input
/// is a finite model.
class ByteChoices : public Choices {
 public:
  ByteChoices(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  int pick(int lo, int hi) override {
    if (at_ >= size_ || hi <= lo) return lo;
    return lo + static_cast<int>(data_[at_++] % static_cast<unsigned>(hi - lo + 1));
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

/// Choices from a seeded Mersenne twister (reproducible).
class SeededChoices : public Choices {
 public:
  explicit SeededChoices(std::uint32_t seed) : rng_(seed) {}
  int pick(int lo, int hi) override { return hi <= lo ? lo : std::uniform_int_distribution<int>(lo, hi)(rng_); }

 private:
  std::mt19937 rng_;
};

/// A framework file (kind: framework): planar or spatial, 1-7 nodes on a small integer grid
/// (so coincident, collinear and coplanar nodes are common), supports from none to every node
/// fixed, 0-10 trusses, beams and rigid bodies.
std::string random_framework_yaml(Choices& choices);
/// A network file (kind: network): 1-6 bodies, 0-9 couplings of random (or all one) types
/// between random bodies, points and directions on a small integer grid.
std::string random_network_yaml(Choices& choices);
/// A structure file (kind: structure): 1-8 bodies joined by a tree of lower and higher pairs and
/// up to 6 more, random inputs.
std::string random_structure_yaml(Choices& choices);
/// One of the three above, the kind chosen first.
std::string random_model_yaml(Choices& choices);

/// What check_model_text found.
struct ModelCheck {
  bool read = false;   ///< the reader accepted the file (else it refused it with a located message)
  std::string failed;  ///< "" when every property held, else what failed (one line)
};

/// Reads `text` as a model file, analyses it, judges it and writes every report, and checks what
/// must hold for any model the readers accept: no exception other than the reader's refusal
/// (io::InputError, a located network::ModelError); for frameworks Maxwell's rule
/// (mechanisms − self-stresses = columns − rows of D(c)), the dense and sparse ranks equal
/// unless the decision is close, and the proposed releases and constraints, applied and
/// re-analysed, leave no mechanism and no self-stress; for networks Davies's identities
/// FN − CN = F − d·l, CN − FN = C − d·k, FN = F − m, CN = C − a, and the exact, floating-point
/// and sparse counts equal unless a decision is close.
ModelCheck check_model_text(const std::string& text);

}  // namespace kinestat::testing
