// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/spacar_reader.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "kinestat/io/input_error.hpp"
#include "kinestat/io/spacar_format.hpp"
#include "kinestat/io/text_file.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::io {

using framework::CoordinateRole;
using framework::DeformationRole;
using framework::Element;
using framework::ElementType;
using framework::FrameworkModel;
using framework::Node;

namespace {

/// The stiffness and mass cards read after the kinematic part (docs/formats.md: as SPACAR Light
/// 1.38 writes them).
const std::set<std::string> kElasticCards = {"ESTIFF", "EM", "XM"};

/// Largest node or element number accepted: keeps every count far from overflow.
constexpr long kMaxNumber = 100'000'000;

struct Token {
  std::string text;
  int line = 0, column = 0;
};

/// One keyword and its numbers (continuation lines that start with a number are appended).
struct Record {
  Token keyword;
  std::vector<Token> values;
};

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

bool starts_number(const std::string& text) {
  const char c = text[0];
  return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.';
}

// What the keywords after END / HALT are about, for the one-line notice.
std::string ignored_summary(const std::set<std::string>& keywords) {
  std::string list;
  for (const auto& k : keywords) list += (list.empty() ? "" : " ") + k;
  return list;
}

class SpacarReader {
 public:
  SpacarReader(std::string path, const std::string& text, std::size_t max_bytes) : path_(std::move(path)) {
    if (text.size() > max_bytes)
      throw InputError({path_, 0, 0}, fmt::format("the input is larger than the {} limit on model files: the command's "
                                                  "--max-input-size SIZE raises it (e.g. 1GiB)",
                                                  size_text(max_bytes)));
    tokenize(text);
  }

  SpacarImport read() {
    // SPACAR files have no title: the model is named after the file.
    model_.name = path_.substr(path_.find_last_of("/\\") == std::string::npos ? 0 : path_.find_last_of("/\\") + 1);
    decide_dimension();
    for (const Record& r : records_)
      if (r.keyword.text == "X") read_position(r);
    for (const Record& r : records_) read_element(r);
    if (elements_.empty())
      fail(end_, "no elements: a SPACAR model needs BEAM, BEAMW, RBEAM, TRUSS, HINGE, PINBODY, PLBEAM, PLTRUSS or PLHINGE lines");
    build_nodes();
    build_elements();
    for (const Record& r : records_) read_role(r);
    read_elastic();
    if (!warped_.empty()) {
      notices_.push_back(fmt::format("{}: note: BEAMW element(s) {} read as BEAM: warping nodes and warping deformations "
                                     "(7, 8) have no counterpart in kinestat and are ignored",
                                     path_, warped_));
    }
    if (!ignored_.empty()) {
      notices_.push_back(fmt::format("{}: note: ignored after the kinematic part (line {}): {} (stiffness, mass, loads, "
                                     "solver steps and visualisation have no kinematic meaning)",
                                     path_, end_.line, ignored_summary(ignored_)));
    }
    return {std::move(model_), std::move(notices_)};
  }

 private:
  [[noreturn]] void fail(const Token& at, const std::string& problem) const {
    throw InputError({path_, at.line, at.column}, problem);
  }

  void tokenize(const std::string& text) {
    bool ended = false;
    int line = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
      std::size_t stop = text.find('\n', start);
      if (stop == std::string::npos) stop = text.size();
      ++line;
      std::vector<Token> tokens;
      for (std::size_t i = start; i < stop;) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == '#' || c == '%') break;  // comment to the end of the line ('%' as in SPACAR's own files)
        if (c == ' ' || c == '\t' || c == '\r' || c == ',') {
          ++i;
          continue;
        }
        if (c < 0x20 || c >= 0x7f)
          throw InputError({path_, line, static_cast<int>(i - start) + 1},
                           "unexpected character: a SPACAR file holds ASCII keywords, numbers and '#' or '%' comments");
        std::size_t j = i;
        while (j < stop && text[j] != ' ' && text[j] != '\t' && text[j] != '\r' && text[j] != ',' && text[j] != '#' && text[j] != '%') {
          const unsigned char d = static_cast<unsigned char>(text[j]);
          if (d < 0x20 || d >= 0x7f)
            throw InputError({path_, line, static_cast<int>(j - start) + 1},
                             "unexpected character: a SPACAR file holds ASCII keywords, numbers and '#' or '%' comments");
          ++j;
        }
        tokens.push_back({text.substr(i, j - i), line, static_cast<int>(i - start) + 1});
        i = j;
      }
      start = stop + 1;
      if (tokens.empty()) continue;
      if (ended) {
        // After END / HALT: the stiffness and mass cards are kept (read_elastic); of the others
        // only the first word, for the notice.
        const std::string word = upper(tokens[0].text);
        elastic_continues_ = (elastic_continues_ && starts_number(word)) || kElasticCards.count(word) != 0;
        if (elastic_continues_ && starts_number(word)) {
          auto& values = elastic_records_.back().values;
          values.insert(values.end(), tokens.begin(), tokens.end());
        } else if (elastic_continues_) {
          tokens[0].text = word;
          elastic_records_.push_back({tokens[0], {tokens.begin() + 1, tokens.end()}});
        } else if (!starts_number(word) && word != "END" && word != "HALT" && ignored_.size() < 64) {
          ignored_.insert(word);
        }
        continue;
      }
      if (starts_number(tokens[0].text)) {
        if (records_.empty()) fail(tokens[0], "expected a keyword (X, BEAM, ...) before numbers");
        auto& values = records_.back().values;
        values.insert(values.end(), tokens.begin(), tokens.end());
        continue;
      }
      tokens[0].text = upper(tokens[0].text);
      if (tokens[0].text == "END" || tokens[0].text == "HALT") {
        ended = true;
        end_ = tokens[0];
        continue;
      }
      records_.push_back({tokens[0], {tokens.begin() + 1, tokens.end()}});
    }
    if (!ended) end_ = {"", line, 1};
  }

  long integer(const Token& token, const std::string& what) const {
    long value = 0;
    const char* first = token.text.data();
    const char* last = first + token.text.size();
    if (*first == '+') ++first;
    const auto [ptr, ec] = std::from_chars(first, last, value);
    if (ec != std::errc() || ptr != last || value < 1 || value > kMaxNumber)
      fail(token, fmt::format("expected {} (a whole number from 1 to {}), found '{}'", what, kMaxNumber, token.text));
    return value;
  }

  double real(const Token& token, const std::string& what) const {
    double value = 0;
    const char* first = token.text.data();
    const char* last = first + token.text.size();
    if (*first == '+') ++first;
    const auto [ptr, ec] = std::from_chars(first, last, value);
    if (ec != std::errc() || ptr != last || !std::isfinite(value))
      fail(token, fmt::format("expected {} (a finite number), found '{}'", what, token.text));
    return value;
  }

  void expect_count(const Record& r, std::initializer_list<std::size_t> counts, const std::string& layout) const {
    if (std::find(counts.begin(), counts.end(), r.values.size()) != counts.end()) return;
    const Token& at = r.values.empty() ? r.keyword : r.values.back();
    fail(at, fmt::format("{} expects {}; found {} number(s)", r.keyword.text, layout, r.values.size()));
  }

  void decide_dimension() {
    const Token* spatial = nullptr;
    const Token* planar = nullptr;
    for (const Record& r : records_) {
      const auto type = spacar::element_keyword(r.keyword.text);
      if (!type) continue;
      if (type->planar && !planar) planar = &r.keyword;
      if (!type->planar && !spatial) spatial = &r.keyword;
    }
    if (spatial && planar) {
      const Token& later = spatial->line > planar->line ? *spatial : *planar;
      fail(later, fmt::format("{} mixes planar and spatial elements ({} on line {}, {} on line {})", later.text,
                              planar->text, planar->line, spatial->text, spatial->line));
    }
    model_.dimension = planar ? 2 : 3;
  }

  void read_position(const Record& r) {
    const std::size_t d = static_cast<std::size_t>(model_.dimension);
    if (model_.dimension == 2) expect_count(r, {3, 4}, "a node number and its coordinates x y (z = 0)");
    else expect_count(r, {4}, "a node number and its coordinates x y z");
    const long n = integer(r.values[0], "a node number");
    if (positions_.count(n)) fail(r.values[0], fmt::format("node {} is defined twice (first on line {})", n, position_lines_[n]));
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i + 1 < r.values.size(); ++i) x(static_cast<Eigen::Index>(i)) = real(r.values[i + 1], "a coordinate");
    if (d == 2 && x.z() != 0.0) fail(r.values[3], "a planar model (PLBEAM, PLTRUSS) lies in the plane z = 0");
    positions_[n] = x;
    position_lines_[n] = r.keyword.line;
    position_order_.push_back(n);
  }

  struct PendingElement {
    Token keyword;
    long number = 0;
    spacar::ElementKind kind = spacar::ElementKind::truss;
    bool warping = false;
    long p = 0, q = 0;    // position nodes (trusses, beams; a pin body's body and carried node)
    long rp = 0, rq = 0;  // orientation nodes (beams and hinges; rp: a pin body's body)
    std::optional<Eigen::Vector3d> y;
    int axis_slot = 5;  // hinges: the slot (rx, ry, rz) of the relative rotation about the axis
    std::vector<Token> node_tokens;
  };

  long position_node(const Token& t) const {
    const long n = integer(t, "a position node number");
    if (!positions_.count(n)) fail(t, fmt::format("node {} has no position: no X line defines it", n));
    return n;
  }

  long orientation_node(const Token& t) const {
    const long n = integer(t, "an orientation node number");
    if (positions_.count(n))
      fail(t, fmt::format("node {} is a position node (defined by X on line {}); an orientation node is expected here", n,
                          position_lines_.at(n)));
    return n;
  }

  // A hinge's axis must lie along a global axis: kinestat's rigid-body coupling of two
  // orientations keeps their relative rotations about the global axes (docs/formats.md).
  int hinge_axis_slot(const Record& r, long number) const {
    Eigen::Vector3d axis;
    for (int i = 0; i < 3; ++i) axis(i) = real(r.values[static_cast<std::size_t>(3 + i)], "the hinge axis");
    Eigen::Index along = 0;
    const double largest = axis.cwiseAbs().maxCoeff(&along);
    if (!(largest > 0)) fail(r.values[3], fmt::format("element {}: the hinge axis is the zero vector", number));
    // Compared with the largest component, so that huge numbers cannot overflow the test.
    const Eigen::Vector3d unit = axis / largest;
    if (std::sqrt(unit.squaredNorm() - 1.0) > kParallelAxes)
      fail(r.values[3], fmt::format("element {}: the hinge axis ({}, {}, {}) is not along a global axis x, y or z; kinestat "
                                    "couples two orientations through their relative rotations about the global axes, so "
                                    "a hinge about another axis is not supported", number, axis.x(), axis.y(), axis.z()));
    return 3 + static_cast<int>(along);
  }

  // A kinematic-part record that is no element: X, role and dynamic cards are read elsewhere,
  // output cards are noted; anything else is refused.
  void skip_or_refuse(const Record& r) {
    const std::string& k = r.keyword.text;
    if (k == "X" || spacar::is_role_keyword(k) || spacar::is_dynamic_keyword(k)) return;
    if (spacar::is_output_keyword(k)) {
      if (ignored_kinematic_.insert(k).second)
        notices_.push_back(fmt::format("{}:{}:{}: note: {} controls SPACAR's output and is ignored", path_, r.keyword.line,
                                       r.keyword.column, k));
      return;
    }
    // CYLINDER, PLRBEAM and SLIDER are SPACAR elements whose cards no public description
    // gives (docs/formats.md): the user is told which cards can replace them.
    const bool element = k == "CYLINDER" || k == "PLRBEAM" || k == "SLIDER";
    fail(r.keyword, fmt::format("unsupported SPACAR keyword '{}' in the kinematic part; kinestat reads {} up to END or HALT{}",
                                k, spacar::kSupportedKeywords,
                                element ? " (no public description of this element's card was found: write the part with "
                                          "BEAM, TRUSS, HINGE and PINBODY elements, docs/formats.md)"
                                        : ""));
  }

  void read_element(const Record& r) {
    const std::string& k = r.keyword.text;
    const auto type = spacar::element_keyword(k);
    if (!type) {
      skip_or_refuse(r);  // no element: read elsewhere, noted, or refused
      return;
    }
    PendingElement e;
    e.keyword = r.keyword;
    e.kind = type->kind;
    e.warping = k == "BEAMW";
    expect_element_count(r);
    e.number = integer(r.values[0], "an element number");
    if (element_lines_.count(e.number))
      fail(r.values[0], fmt::format("element {} is defined twice (first on line {})", e.number, element_lines_[e.number]));
    element_lines_[e.number] = r.keyword.line;
    read_element_nodes(r, e);
    if (e.kind != spacar::ElementKind::hinge && e.p == e.q)
      fail(e.node_tokens.back(), fmt::format("element {} connects node {} to itself", e.number, e.p));
    if ((e.kind == spacar::ElementKind::beam || e.kind == spacar::ElementKind::hinge) && e.rp == e.rq)
      fail(e.node_tokens.back(), fmt::format("element {} has the same orientation node {} at both ends", e.number, e.rp));
    elements_.push_back(std::move(e));
  }

  // The count of numbers each element card takes.
  void expect_element_count(const Record& r) const {
    const std::string& k = r.keyword.text;
    if (k == "TRUSS" || k == "PLTRUSS") {
      expect_count(r, {3}, "an element number and two position nodes");
    } else if (k == "PLBEAM") {
      expect_count(r, {5}, "an element number, position and orientation node at p, then at q");
    } else if (k == "BEAM") {
      expect_count(r, {5, 8}, "an element number, position and orientation node at p, then at q, and the local y direction");
    } else if (k == "BEAMW") {
      expect_count(r, {7, 10},
                   "an element number, position, orientation and warping node at p, then at q, and the local y direction");
    } else if (k == "HINGE") {
      expect_count(r, {6}, "an element number, two orientation nodes and the hinge axis x y z");
    } else if (k == "PLHINGE") {
      expect_count(r, {3}, "an element number and two orientation nodes");
    } else if (k == "RBEAM") {
      expect_count(r, {4, 7}, "an element number, the position and orientation node at p, the position node q, and the "
                              "local y direction");
    } else {
      expect_count(r, {4}, "an element number, the position and orientation node of the body, and the position node it carries");
    }
  }

  // The nodes of element card `r` (and a beam's local y, a hinge's axis) into `e`.
  void read_element_nodes(const Record& r, PendingElement& e) {
    const std::string& k = r.keyword.text;
    switch (e.kind) {
      case spacar::ElementKind::truss:
        e.p = position_node(r.values[1]);
        e.q = position_node(r.values[2]);
        e.node_tokens = {r.values[1], r.values[2]};
        break;
      case spacar::ElementKind::hinge:
        e.rp = orientation_node(r.values[1]);
        e.rq = orientation_node(r.values[2]);
        e.node_tokens = {r.values[1], r.values[2]};
        if (k == "HINGE") e.axis_slot = hinge_axis_slot(r, e.number);
        break;
      case spacar::ElementKind::pin_body:
      case spacar::ElementKind::rigid_beam:  // the local y direction orients the section only
        e.p = position_node(r.values[1]);
        e.rp = orientation_node(r.values[2]);
        e.q = position_node(r.values[3]);
        e.node_tokens = {r.values[1], r.values[2], r.values[3]};
        break;
      case spacar::ElementKind::beam: {
        const std::size_t stride = e.warping ? 3 : 2;
        e.p = position_node(r.values[1]);
        e.rp = orientation_node(r.values[2]);
        e.q = position_node(r.values[1 + stride]);
        e.rq = orientation_node(r.values[2 + stride]);
        e.node_tokens = {r.values[1], r.values[2], r.values[1 + stride], r.values[2 + stride]};
        if (e.warping) {
          // Warping nodes carry the warping deformation only; FIX or INPUTX on them is ignored.
          warping_nodes_.insert(integer(r.values[3], "a warping node number"));
          warping_nodes_.insert(integer(r.values[6], "a warping node number"));
          warped_ += (warped_.empty() ? "" : ", ") + std::to_string(e.number);
        }
        const std::size_t y_at = 1 + 2 * stride;
        if (r.values.size() == y_at + 3) {
          e.y = Eigen::Vector3d(real(r.values[y_at], "the local y direction"), real(r.values[y_at + 1], "the local y direction"),
                                real(r.values[y_at + 2], "the local y direction"));
        }
        break;
      }
    }
  }

  // Each orientation node belongs to one position node; the first orientation node seen at a
  // position rides on that position's node, any further one gets a joint node of its own.
  void attach(long position, long orientation, const Token& at) {
    const auto found = orientation_owner_.find(orientation);
    if (found != orientation_owner_.end()) {
      if (found->second != position)
        fail(at, fmt::format("orientation node {} is used at position node {} and at position node {}: an orientation node "
                             "belongs to one position", orientation, found->second, position));
      return;
    }
    orientation_owner_[orientation] = position;
    auto& list = orientations_at_[position];
    list.push_back(orientation);
  }

  // The carried position node that the second orientation node `rq` of a hinge on `rp` belongs
  // to, or 0 to leave it to the numbering rule. SPACAR Light's own files have rq − 1 among the
  // nodes carried by the pin body on rp; a pin body that carries several nodes (or one that a
  // hinge before already turned) is ambiguous, and a carried node that already has an
  // orientation would take rq as a second, jointed one: then the numbering decides when a
  // position node rq − 1 exists (kinestat's SPACAR writer relies on it for the nodes it joins by
  // a PINBODY; found by fuzz_spacar_file), and the first carried node only when none does.
  long hinge_carrier(const std::multimap<long, long>& carried_by_body, long rp, long rq) const {
    if (orientation_owner_.count(rq)) return 0;
    const auto [first, last] = carried_by_body.equal_range(rp);
    if (first == last) return 0;
    for (auto it = first; it != last; ++it)
      if (it->second == rq - 1) return it->second;
    for (auto it = first; it != last; ++it)
      if (!orientations_at_.count(it->second) || orientations_at_.at(it->second).empty()) return it->second;
    return positions_.count(rq - 1) ? 0 : first->second;
  }

  void build_nodes() {
    using spacar::ElementKind;
    std::multimap<long, long> carried_by_body;  // a pin body's orientation node -> the position node it carries
    for (const PendingElement& e : elements_) {
      if (e.kind == ElementKind::beam) {
        attach(e.p, e.rp, e.node_tokens[1]);
        attach(e.q, e.rq, e.node_tokens[3]);
      } else if (e.kind == ElementKind::pin_body) {
        attach(e.p, e.rp, e.node_tokens[1]);
        carried_by_body.emplace(e.rp, e.q);
      } else if (e.kind == ElementKind::rigid_beam) {
        attach(e.p, e.rp, e.node_tokens[1]);
      }
    }
    // SPACAR Light writes a hinge between user nodes p and q as HINGE e rp rq and PINBODY e+1
    // xp rp xq: the hinge's second orientation node rq belongs to the carried position node xq.
    // An orientation node still without a position belongs to the position node numbered one
    // below it, as SPACAR Light numbers them (2i-1, 2i in 1.23; 3i-2, 3i-1 in 1.37). A hinge
    // couples orientations only, so the position chosen never changes what can move.
    for (const PendingElement& h : elements_) {
      if (h.kind != ElementKind::hinge) continue;
      if (const long carrier = hinge_carrier(carried_by_body, h.rp, h.rq); carrier != 0) attach(carrier, h.rq, h.node_tokens[1]);
      for (std::size_t k = 0; k < 2; ++k) {
        const long r = k == 0 ? h.rp : h.rq;
        if (!orientation_owner_.count(r) && positions_.count(r - 1)) attach(r - 1, r, h.node_tokens[k]);
      }
    }
    // An orientation node that only hinges use (SPACAR's rigid catheter chains three hinges
    // through two such nodes to make a spherical joint) takes the position of the hinge's other
    // orientation node, repeated until the chain is placed.
    for (bool placed = true; placed;) {
      placed = false;
      for (const PendingElement& h : elements_) {
        if (h.kind != ElementKind::hinge) continue;
        const bool has_p = orientation_owner_.count(h.rp) != 0, has_q = orientation_owner_.count(h.rq) != 0;
        if (has_p == has_q) continue;
        if (has_p) attach(orientation_owner_.at(h.rp), h.rq, h.node_tokens[1]);
        else attach(orientation_owner_.at(h.rq), h.rp, h.node_tokens[0]);
        placed = true;
      }
    }
    for (const PendingElement& h : elements_) {
      if (h.kind != ElementKind::hinge) continue;
      for (std::size_t k = 0; k < 2; ++k) {
        const long r = k == 0 ? h.rp : h.rq;
        if (!orientation_owner_.count(r))
          fail(h.node_tokens[k], fmt::format("orientation node {} of hinge {} belongs to no position node: no BEAM, RBEAM or "
                                             "PINBODY uses it or a node hinged to it, and no X line defines node {}",
                                             r, h.number, r - 1));
      }
    }
    // An RBEAM's end q without an orientation node is given the body's rotations (see
    // build_elements).
    for (const PendingElement& e : elements_)
      if (e.kind == ElementKind::rigid_beam && orientations_at_[e.q].empty()) welded_ends_.insert(e.q);
    for (long n : position_order_) {
      Node node;
      node.name = spacar_node_name(n);
      node.position = positions_[n];
      const auto& list = orientations_at_[n];
      node.rotational = !list.empty() || welded_ends_.count(n) != 0;
      position_index_[n] = model_.nodes.size();
      if (!list.empty()) orientation_index_[list[0]] = model_.nodes.size();
      model_.nodes.push_back(std::move(node));
    }
    for (long n : position_order_) {
      const auto& list = orientations_at_[n];
      for (std::size_t k = 1; k < list.size(); ++k) {
        Node node;
        node.name = spacar_joint_node_name(n, list[k]);
        node.position = positions_[n];
        node.rotational = true;
        orientation_index_[list[k]] = model_.nodes.size();
        joints_.push_back({position_index_[n], model_.nodes.size()});
        model_.nodes.push_back(std::move(node));
      }
    }
  }

  // Every pending element as a framework element (named by its SPACAR number), then the joints.
  void build_elements() {
    // Once: the nodes do not change while elements are built (per element it was O(n^2)).
    coincident_distance_ = kCoincident * framework::characteristic_length(model_);
    for (const PendingElement& e : elements_) {
      Element element;
      element.name = std::to_string(e.number);
      switch (e.kind) {
        case spacar::ElementKind::hinge: build_hinge(e, element); break;
        case spacar::ElementKind::pin_body: build_pin_body(e, element); break;
        case spacar::ElementKind::rigid_beam: build_rigid_beam(e, element); break;
        case spacar::ElementKind::truss:
        case spacar::ElementKind::beam: build_bar_or_beam(e, element); break;
      }
      element_index_[e.number] = model_.elements.size();
      element_types_.push_back(&e);
      model_.elements.push_back(std::move(element));
    }
    build_joints();
  }

  std::size_t translation_count() const { return model_.dimension == 2 ? 2 : 3; }

  // Two orientations joined: relative translations free, relative rotations rigid (the one
  // about the axis is deformation 1; see read_role).
  void build_hinge(const PendingElement& e, Element& element) const {
    element.type = ElementType::rigid_body;
    element.nodes = {orientation_index_.at(e.rp), orientation_index_.at(e.rq)};
    element.roles.assign(framework::deformation_count(model_.dimension, element), DeformationRole::fixed);
    for (std::size_t k = 0; k < translation_count(); ++k) element.roles[k] = DeformationRole::released;
  }

  // The carried position node moves with the body; its orientation is free.
  void build_pin_body(const PendingElement& e, Element& element) const {
    const std::size_t carried = position_index_.at(e.q);
    if (!model_.nodes[carried].rotational)
      fail(e.node_tokens[2], fmt::format("PINBODY {} carries position node {}, which no BEAM or HINGE gives an "
                                         "orientation node: kinestat cannot pin a node without one to a body",
                                         e.number, e.q));
    element.type = ElementType::rigid_body;
    element.nodes = {orientation_index_.at(e.rp), carried};
    element.roles.assign(framework::deformation_count(model_.dimension, element), DeformationRole::released);
    for (std::size_t k = 0; k < translation_count(); ++k) element.roles[k] = DeformationRole::fixed;
  }

  // RBEAM e p rp q: q = p + R(rp)·(q0 − p0), three constraints, and q has no orientation
  // node of its own. A rigid body on rp (its reference node: position p, orientation rp)
  // carrying q holds q's three relative translations. Framework rigid-body nodes are
  // rotational, so q's relative rotations must be dealt with without changing the count:
  // when q has an orientation from another element (the next link's rp) they are
  // released, as in PINBODY (3 constraints); when it has none, q is given three rotations
  // that are held to the body's (3 coordinates and 3 constraints more, which determine
  // each other, so the motions and redundancies are those of the 3 constraints alone). A
  // beam with every deformation held would also hold q's orientation, which is not
  // SPACAR's RBEAM when q carries one.
  void build_rigid_beam(const PendingElement& e, Element& element) const {
    const std::size_t carried = position_index_.at(e.q);
    element.type = ElementType::rigid_body;
    element.nodes = {orientation_index_.at(e.rp), carried};
    const bool welded = welded_ends_.count(e.q) != 0;
    element.roles.assign(framework::deformation_count(model_.dimension, element),
                         welded ? DeformationRole::fixed : DeformationRole::released);
    for (std::size_t k = 0; k < translation_count(); ++k) element.roles[k] = DeformationRole::fixed;
    const Eigen::Vector3d axis = model_.nodes[carried].position - model_.nodes[element.nodes[0]].position;
    if (!(axis.norm() > coincident_distance_))
      fail(e.node_tokens.back(), fmt::format("zero-length element {}: nodes {} and {} coincide", e.number, e.p, e.q));
  }

  // A truss between position nodes, or a beam between the nodes of its orientation nodes with
  // its local frame (SPACAR Light's default local y is the global y axis).
  void build_bar_or_beam(const PendingElement& e, Element& element) const {
    const bool beam = e.kind == spacar::ElementKind::beam;
    element.type = beam ? ElementType::beam : ElementType::truss;
    const std::size_t p = beam ? orientation_index_.at(e.rp) : position_index_.at(e.p);
    const std::size_t q = beam ? orientation_index_.at(e.rq) : position_index_.at(e.q);
    element.nodes = {p, q};
    const Eigen::Vector3d axis = model_.nodes[q].position - model_.nodes[p].position;
    if (!(axis.norm() > coincident_distance_))
      fail(e.node_tokens.back(), fmt::format("zero-length element {}: nodes {} and {} coincide", e.number, e.p, e.q));
    const Eigen::Vector3d x = axis.normalized();
    if (beam) {
      if (model_.dimension == 2) {
        element.frame << x, Eigen::Vector3d::UnitZ().cross(x), Eigen::Vector3d::UnitZ();
      } else {
        const Eigen::Vector3d given = e.y.value_or(Eigen::Vector3d::UnitY());
        const Eigen::Vector3d across = given - given.dot(x) * x;
        if (!(given.norm() > 0) || !(across.norm() > kParallelAxes * given.norm()))
          fail(e.keyword, fmt::format("element {}: the local y direction ({}, {}, {}) is parallel to the element "
                                      "axis from node {} to node {}", e.number, given.x(), given.y(), given.z(), e.p, e.q));
        const Eigen::Vector3d y = across.normalized();
        element.frame << x, y, x.cross(y);
      }
    }
    element.roles.assign(framework::deformation_count(model_.dimension, element), DeformationRole::fixed);
  }

  // A position shared by several orientation nodes is a joint: the positions stay together,
  // the orientations are free relative to each other (a spherical joint in 3-D, a pin in 2-D).
  void build_joints() {
    for (const auto& [a, b] : joints_) {
      Element joint;
      joint.name = "joint " + model_.nodes[b].name;
      joint.type = ElementType::rigid_body;
      joint.nodes = {a, b};
      joint.roles.assign(framework::deformation_count(model_.dimension, joint), DeformationRole::fixed);
      for (std::size_t k = translation_count(); k < joint.roles.size(); ++k) joint.roles[k] = DeformationRole::released;
      model_.elements.push_back(std::move(joint));
    }
  }

  // The stiffness and mass cards (docs/formats.md, after spacarlight.m 1.38): ESTIFF e EA GIt EIy
  // EIz [cy cz [ECw]] and EM e ρA [rotational inertias per length] of a spatial beam become a
  // section given by its rigidities (named "ESTIFF e"); XM n m on a position node and XM n Ixx
  // Ixy Ixz Iyy Iyz Izz on an orientation node become the node's lumped mass and inertia. What
  // kinestat has no counterpart for (shear flexibility, warping, rotational inertia per length,
  // products of inertia, cards on other elements) is left out with one note each.
  void read_elastic() {
    std::map<long, std::size_t> section_of;  // SPACAR element -> its ESTIFF section
    for (const std::string pass : {"ESTIFF", "EM", "XM"})
      for (const Record& r : elastic_records_)
        if (r.keyword.text == pass) pass == "XM" ? read_node_mass(r) : read_element_elastic(r, section_of);
  }

  void elastic_note(const Record& r, const std::string& what) {
    notices_.push_back(fmt::format("{}:{}:{}: note: {} {}", path_, r.keyword.line, r.keyword.column, r.keyword.text, what));
  }

  void read_element_elastic(const Record& r, std::map<long, std::size_t>& section_of) {
    const bool stiffness = r.keyword.text == "ESTIFF";
    if (r.values.size() < 2) expect_count(r, {stiffness ? 5u : 2u}, "an element number and its values");
    const long number = integer(r.values[0], "an element number");
    const auto found = element_index_.find(number);
    if (found == element_index_.end()) fail(r.values[0], fmt::format("{}: no element {}", r.keyword.text, number));
    const framework::Element& element = model_.elements[found->second];
    if (element.type != ElementType::beam || model_.dimension != 3 || (!stiffness && !section_of.count(number))) {
      elastic_note(r, fmt::format("of element {} ignored: kinestat reads ESTIFF and EM of spatial beams (EM after an ESTIFF)", number));
      return;
    }
    if (stiffness) expect_count(r, {5, 7, 8}, "an element number, EA, GIt, EIy, EIz, and optionally the shear terms and ECw");
    std::vector<double> v;
    for (std::size_t i = 1; i < r.values.size(); ++i) v.push_back(real(r.values[i], "a stiffness or mass value"));
    if (!stiffness) {
      model_.sections[section_of[number]].mass_per_length = v[0];
      if (std::any_of(v.begin() + 1, v.end(), [](double x) { return x != 0.0; }))
        elastic_note(r, fmt::format("of element {}: the rotational inertias per length are ignored (kinestat lumps an "
                                    "element's mass on its nodes' translations)", number));
      return;
    }
    framework::Section section;
    section.name = "ESTIFF " + std::to_string(number);
    section.shape = framework::SectionShape::rigidities;
    section.area = v[0], section.torsion = v[1], section.iy = v[2], section.iz = v[3];
    if (std::any_of(v.begin() + 4, v.end(), [](double x) { return x != 0.0; }))
      elastic_note(r, fmt::format("of element {}: the shear-flexibility and warping terms are ignored (Euler-Bernoulli beams)", number));
    section_of[number] = model_.sections.size();
    model_.elements[found->second].section = model_.sections.size();
    model_.sections.push_back(std::move(section));
  }

  void read_node_mass(const Record& r) {
    expect_count(r, {2, 7}, "a position node and its mass, or an orientation node and Ixx Ixy Ixz Iyy Iyz Izz");
    const long number = integer(r.values[0], "a node number");
    const bool inertia = r.values.size() == 7;
    const auto& index = inertia ? orientation_index_ : position_index_;
    const auto found = index.find(number);
    if (found == index.end()) {
      elastic_note(r, fmt::format("of node {} ignored: no {} node of the model carries it", number, inertia ? "orientation" : "position"));
      return;
    }
    std::vector<double> v;
    for (std::size_t i = 1; i < r.values.size(); ++i) v.push_back(real(r.values[i], "a mass or inertia value"));
    if (inertia && (v[1] != 0.0 || v[2] != 0.0 || v[4] != 0.0)) {
      elastic_note(r, fmt::format("of node {} ignored: kinestat's node inertia has no products of inertia (Ixy, Ixz, Iyz)", number));
      return;
    }
    auto mass = std::find_if(model_.masses.begin(), model_.masses.end(), [&](const auto& m) { return m.node == found->second; });
    if (mass == model_.masses.end()) mass = model_.masses.insert(model_.masses.end(), framework::NodeMass{found->second, 0.0, std::nullopt});
    if (inertia) mass->inertia = Eigen::Vector3d(v[0], v[3], v[5]);
    else mass->mass += v[0];
  }

  // DYNX: the nodal coordinates that SPACAR's dynamic analysis integrates, its degrees of
  // freedom. SPACAR requires the input (INPUTX, INPUTE) and dynamic coordinates together to
  // determine the configuration, so they are read as kinestat's independent coordinates: a
  // model SPACAR accepts then has no free motion left and no redundant constraint (0/0).
  void read_dynamic(const Record& r) {
    const std::string& k = r.keyword.text;
    if (r.values.empty()) fail(r.keyword, fmt::format("{} expects a node number", k));
    read_coordinates(r, CoordinateRole::independent);
    if (ignored_kinematic_.insert(k).second)
      notices_.push_back(fmt::format("{}:{}:{}: note: {} coordinates (the degrees of freedom of SPACAR's dynamic analysis) read "
                                     "as independent coordinates, as INPUTX: SPACAR needs them and the inputs to determine the "
                                     "configuration, so a model it accepts has 0 extra motions",
                                     path_, r.keyword.line, r.keyword.column, k));
  }

  // DYNE, RLSE and INPUTE (deformations of an element), FIX and INPUTX (nodal coordinates).
  void read_role(const Record& r) {
    const std::string& k = r.keyword.text;
    if (spacar::is_dynamic_keyword(k)) return read_dynamic(r);
    if (!spacar::is_role_keyword(k)) return;
    if (r.values.empty()) fail(r.keyword, fmt::format("{} expects a{} number", k, k == "FIX" || k == "INPUTX" ? " node" : "n element"));
    if (k == "FIX" || k == "INPUTX") return read_coordinates(r, k == "FIX" ? CoordinateRole::fixed : CoordinateRole::independent);
    const long number = integer(r.values[0], "an element number");
    const auto found = element_index_.find(number);
    if (found == element_index_.end()) fail(r.values[0], fmt::format("{}: there is no element {}", k, number));
    Element& element = model_.elements[found->second];
    const PendingElement& pending = *element_types_[found->second];
    const DeformationRole role =
        k == "RLSE" ? DeformationRole::released : (k == "INPUTE" ? DeformationRole::independent : DeformationRole::fixed);
    if (pending.kind == spacar::ElementKind::pin_body && role != DeformationRole::fixed)
      fail(r.keyword, fmt::format("{} of PINBODY {}: kinestat keeps a pin body rigid (its deformations are not documented "
                                  "publicly, so which is which is not known)", k, number));
    if (pending.kind == spacar::ElementKind::rigid_beam && role != DeformationRole::fixed)
      fail(r.keyword, fmt::format("{} of RBEAM {}: a rigid beam has no deformation to release; write a BEAM to let it deform",
                                  k, number));
    const std::vector<int> map = deformation_map(pending, element);
    std::vector<std::size_t> list;  // SPACAR deformation numbers - 1
    if (r.values.size() == 1) {
      for (std::size_t d = 0; d < map.size(); ++d) list.push_back(d);  // no numbers: every deformation
    }
    for (std::size_t i = 1; i < r.values.size(); ++i) {
      const long d = integer(r.values[i], "a deformation number");
      if (static_cast<std::size_t>(d) > map.size())
        fail(r.values[i], fmt::format("element {} ({}) has deformations 1 to {}, found {}", number, pending.keyword.text,
                                      map.size(), d));
      list.push_back(static_cast<std::size_t>(d - 1));
    }
    if (pending.kind == spacar::ElementKind::hinge && map.size() == 3 &&
        std::count(list.begin(), list.end(), 1) != std::count(list.begin(), list.end(), 2))
      fail(r.keyword, fmt::format("{} of HINGE {}: deformations 2 and 3 (the relative rotations about the two axes across "
                                  "the hinge axis) must be given together; which is which is not documented publicly",
                                  k, number));
    for (std::size_t d : list) {
      auto& seen = deformation_keyword_[{number, d}];
      if (!seen.empty() && seen != k)
        fail(r.keyword, fmt::format("deformation {} of element {} is both {} and {}", d + 1, number, seen, k));
      seen = k;
      if (map[d] >= 0) element.roles[static_cast<std::size_t>(map[d])] = role;  // -1: a warping deformation of BEAMW
    }
  }

  // SPACAR's deformation numbers (minus 1) of `e` -> the deformations of its kinestat element
  // (-1: not modelled). Hinge: 1 is the rotation about the axis, 2 and 3 those across it.
  static std::vector<int> deformation_map(const PendingElement& e, const Element& element) {
    if (e.kind == spacar::ElementKind::hinge) {
      if (element.roles.size() == 3) return {2};  // planar: x, y, rz
      std::vector<int> map = {e.axis_slot};
      for (int slot = 3; slot < 6; ++slot)
        if (slot != e.axis_slot) map.push_back(slot);
      return map;
    }
    if (e.kind == spacar::ElementKind::pin_body || e.kind == spacar::ElementKind::rigid_beam) return {0, 1, 2};
    std::vector<int> map;
    for (std::size_t d = 0; d < element.roles.size(); ++d) map.push_back(static_cast<int>(d));
    if (e.warping) map.insert(map.end(), {-1, -1});
    return map;
  }

  void read_coordinates(const Record& r, CoordinateRole role) {
    const std::string& k = r.keyword.text;
    const long n = integer(r.values[0], "a node number");
    std::vector<int> slots;
    Node* node = nullptr;
    std::vector<int> available;  // SPACAR coordinate number - 1 -> kinestat slot (-1: none)
    if (const auto p = position_index_.find(n); p != position_index_.end()) {
      node = &model_.nodes[p->second];
      available = model_.dimension == 2 ? std::vector<int>{0, 1} : std::vector<int>{0, 1, 2};
    } else if (const auto o = orientation_index_.find(n); o != orientation_index_.end()) {
      node = &model_.nodes[o->second];
      // Spatial orientation nodes are Euler parameters λ0..λ3: λ1, λ2, λ3 follow the rotations
      // about x, y, z (SPACAR Light writes INPUTX n 4 for rot_x... see docs/formats.md).
      available = model_.dimension == 2 ? std::vector<int>{5} : std::vector<int>{-1, 3, 4, 5};
    } else if (warping_nodes_.count(n)) {
      if (ignored_kinematic_.insert("warping " + k).second)
        notices_.push_back(fmt::format("{}:{}:{}: note: {} of warping node {} ignored (warping is not modelled)", path_,
                                       r.keyword.line, r.keyword.column, k, n));
      return;
    } else {
      fail(r.values[0], fmt::format("{}: node {} is neither an X position node nor an orientation node of a beam", k, n));
    }
    if (r.values.size() == 1) {
      for (int s : available)
        if (s >= 0) slots.push_back(s);
    }
    for (std::size_t i = 1; i < r.values.size(); ++i) {
      const long c = integer(r.values[i], "a coordinate number");
      if (static_cast<std::size_t>(c) > available.size())
        fail(r.values[i], fmt::format("node {} has coordinates 1 to {}, found {}", n, available.size(), c));
      const int slot = available[static_cast<std::size_t>(c - 1)];
      if (slot < 0) {
        notices_.push_back(fmt::format("{}:{}:{}: note: {} of Euler parameter λ0 of node {} has no kinematic meaning of its "
                                       "own and is ignored", path_, r.values[i].line, r.values[i].column, k, n));
        continue;
      }
      slots.push_back(slot);
    }
    for (int s : slots) {
      auto& current = node->roles[static_cast<std::size_t>(s)];
      if (current != CoordinateRole::dependent && current != role)
        fail(r.keyword, fmt::format("coordinate {} of node {} is both fixed (FIX) and prescribed (INPUTX)",
                                    framework::kSlotNames[static_cast<std::size_t>(s)], n));
      current = role;
    }
  }

  std::string path_;
  std::vector<Record> records_;
  std::vector<Record> elastic_records_;  // ESTIFF, EM, XM after END (read_elastic)
  bool elastic_continues_ = false;       // the last line after END was one of them
  Token end_;
  std::set<std::string> ignored_;
  std::set<std::string> ignored_kinematic_;
  std::set<long> warping_nodes_;
  std::vector<std::string> notices_;
  std::set<long> welded_ends_;  // RBEAM end nodes q without an orientation node (given the body's rotations)
  double coincident_distance_ = 0.0;  ///< kCoincident × the characteristic length, set by build_elements
  std::string warped_;
  FrameworkModel model_;
  std::map<long, Eigen::Vector3d> positions_;
  std::map<long, int> position_lines_;
  std::vector<long> position_order_;
  std::map<long, int> element_lines_;
  std::vector<PendingElement> elements_;
  std::map<long, long> orientation_owner_;
  std::map<long, std::vector<long>> orientations_at_;
  std::map<long, std::size_t> position_index_, orientation_index_;
  std::vector<std::pair<std::size_t, std::size_t>> joints_;
  std::map<long, std::size_t> element_index_;
  std::vector<const PendingElement*> element_types_;
  std::map<std::pair<long, std::size_t>, std::string> deformation_keyword_;
};

}  // namespace

std::string spacar_node_name(long position) { return std::to_string(position); }

std::string spacar_joint_node_name(long position, long orientation) {
  return fmt::format("{}r{}", position, orientation);
}

SpacarImport parse_spacar(const std::string& path, const std::string& text, const ImportOptions& options) {
  return SpacarReader(path, text, options.max_input_bytes).read();
}

SpacarImport read_spacar(const std::string& path, const ImportOptions& options) {
  return parse_spacar(path, read_text_file(path, options.max_input_bytes), options);
}

}  // namespace kinestat::io
