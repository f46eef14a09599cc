// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/spacar_writer.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>

#include <map>
#include <set>

#include "kinestat/framework/elastic_properties.hpp"
#include "kinestat/io/input_error.hpp"
#include "kinestat/io/printable_text.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::io {

using framework::CoordinateRole;
using framework::DeformationRole;
using framework::Element;
using framework::ElementType;
using framework::FrameworkModel;

namespace {


std::string spacar_number(double value) { return fmt::format("{}", value == 0.0 ? 0.0 : value); }

class SpacarWriter {
 public:
  SpacarWriter(const FrameworkModel& model, const SpacarWriteOptions& options) : model_(model), options_(options) {}

  std::string write() {
    planar_ = model_.dimension == 2;
    number_nodes();
    header();
    positions();
    elements();
    roles(model_, out_);
    if (options_.proposed) proposal();
    out_ += "\nEND\nHALT\n";
    if (model_.has_elastic_data()) elastic();
    return out_;
  }

 private:
  [[noreturn]] void refuse(const std::string& problem) const { throw InputError({options_.source, 0, 0}, problem); }

  // The stiffness and mass cards after the kinematic part, as SPACAR Light writes them
  // (docs/formats.md): ESTIFF e EA GIt EIy EIz 0 0 (no shear flexibility: Euler-Bernoulli) and
  // EM e ρA ρ(Iy+Iz) ρIy ρIz 0 for every spatial beam with elastic data, XM on the nodes with a
  // mass (position node) and an inertia (orientation node, no products). A truss's cards are
  // not written: no public description of their layout was found.
  void elastic() {
    out_ += "\n#STIFFNESS  Ne  EA  GIt  EIy  EIz  shear y  shear z   (kinestat's elastic data; consistent units)\n";
    std::string masses = "\n#MASS  Ne  M/L  Jxx/L  Jyy/L  Jzz/L  Jyz/L\n";
    for (std::size_t e = 0, n = 0; e < model_.elements.size(); ++e) {
      const Element& element = model_.elements[e];
      if (is_shared_joint(element)) continue;
      const long number = number_[n++];
      const framework::Section* section = framework::element_section(model_, element);
      const framework::Material* material = framework::element_material(model_, element);
      const bool rigidities = section && section->shape == framework::SectionShape::rigidities;
      if (planar_ || element.type != ElementType::beam || !section || (!material && !rigidities)) continue;
      const double e_modulus = rigidities ? 1.0 : material->youngs_modulus, g = rigidities ? 1.0 : framework::shear_modulus(*material);
      out_ += fmt::format("ESTIFF  {:4}  {}  {}  {}  {}  0  0  # {}\n", number, spacar_number(e_modulus * section->area),
                          spacar_number(g * section->torsion), spacar_number(e_modulus * section->iy),
                          spacar_number(e_modulus * section->iz), printable_text(element.name));
      const double rho = rigidities || !material->density ? 0.0 : *material->density;
      const double per_length = rigidities ? section->mass_per_length : rho * section->area;
      if (per_length > 0.0)
        masses += fmt::format("EM  {:4}  {}  {}  {}  {}  0  # {}\n", number, spacar_number(per_length),
                              spacar_number(rho * (section->iy + section->iz)), spacar_number(rho * section->iy),
                              spacar_number(rho * section->iz), printable_text(element.name));
    }
    out_ += masses + "\n#NODAL MASS  Nn  M, or Ixx Ixy Ixz Iyy Iyz Izz\n";
    for (const framework::NodeMass& m : model_.masses) {
      const std::string name = printable_text(model_.nodes[m.node].name);
      if (m.mass != 0.0) out_ += fmt::format("XM  {:6}  {}  # node {}\n", position_[m.node], spacar_number(m.mass), name);
      if (m.inertia && !planar_ && used_orientations_.count(m.node))
        out_ += fmt::format("XM  {:6}  {}  0  0  {}  0  {}  # node {} inertia\n", orientation(m.node), spacar_number(m.inertia->x()),
                            spacar_number(m.inertia->y()), spacar_number(m.inertia->z()), name);
    }
    out_ += "END\nEND\n";
  }

  bool is_joint(const Element& e) const { return holds_translations_only(e) && coincident(e); }

  // A spatial two-node rigid body that holds the second node's position in the first node's
  // frame and leaves its orientation free is a SPACAR PINBODY also when the nodes are apart
  // (the reader makes exactly this element of a PINBODY whose position nodes differ).
  bool is_offset_pin_body(const Element& e) const { return !planar_ && holds_translations_only(e) && !coincident(e); }

  // Relative translations fixed, relative rotations released.
  bool holds_translations_only(const Element& e) const {
    if (e.type != ElementType::rigid_body || e.nodes.size() != 2) return false;
    const std::size_t translations = planar_ ? 2 : 3;
    for (std::size_t k = 0; k < e.roles.size(); ++k) {
      const DeformationRole want = k < translations ? DeformationRole::fixed : DeformationRole::released;
      if (e.roles[k] != want) return false;
    }
    return true;
  }

  bool coincident(const Element& e) const {
    const double length = framework::characteristic_length(model_);
    return (model_.nodes[e.nodes[0]].position - model_.nodes[e.nodes[1]].position).norm() <= kCoincident * length;
  }

  // A two-node rigid body whose relative translations are released couples the orientations
  // only: a SPACAR HINGE (PLHINGE in 2-D). Its axis is the global axis whose relative rotation
  // has a role of its own (deformation 1); the two others (2 and 3) share one. -1: not a hinge.
  int hinge_axis(const Element& e) const {
    if (e.type != ElementType::rigid_body || e.nodes.size() != 2) return -1;
    const std::size_t translations = planar_ ? 2 : 3;
    for (std::size_t k = 0; k < translations; ++k)
      if (e.roles[k] != DeformationRole::released) return -1;
    if (planar_) return 5;
    const auto& r = e.roles;
    if (r[3] == r[4] && r[4] == r[5]) return 5;
    if (r[4] == r[5]) return 3;
    if (r[3] == r[5]) return 4;
    if (r[3] == r[4]) return 5;
    return -1;
  }

  // SPACAR Light's numbering: node i (1-based) has position node 2i−1 and orientation node 2i.
  // The second node of a joint shares the first node's position node, unless only hinges use
  // its orientation: then no BEAM would tie that orientation node to the shared position, so
  // the node keeps its own position node (numbered one below its orientation node, which the
  // reader relies on) and the joint is written as a PINBODY, as SPACAR Light writes the pin of
  // a hinge. SPACAR has no planar pin body: such a planar joint is refused.
  void number_nodes() {
    std::set<std::size_t> hinged, beamed;
    for (const Element& e : model_.elements) {
      if (hinge_axis(e) >= 0) hinged.insert(e.nodes.begin(), e.nodes.end());
      else if (is_offset_pin_body(e))
        beamed.insert(e.nodes[0]);  // the pin body ties only its first node's orientation to a position
      else if (e.type == ElementType::beam || (e.type == ElementType::rigid_body && !is_joint(e)))
        beamed.insert(e.nodes.begin(), e.nodes.end());
    }
    for (std::size_t n : hinged)
      if (!beamed.count(n)) hinge_only_.insert(n);
    std::vector<std::size_t> owner(model_.nodes.size());
    for (std::size_t i = 0; i < owner.size(); ++i) owner[i] = i;
    const auto root = [&](std::size_t i) {
      while (owner[i] != i) i = owner[i];
      return i;
    };
    for (const Element& e : model_.elements) {
      if (!is_joint(e)) continue;
      if (!is_shared_joint(e)) {
        if (planar_)
          refuse(fmt::format("joint '{}': node '{}' turns only through PLHINGE elements, so it needs a position node of "
                             "its own, and SPACAR has no planar pin body to join it to '{}'", e.name,
                             model_.nodes[e.nodes[1]].name, model_.nodes[e.nodes[0]].name));
        continue;
      }
      owner[root(e.nodes[1])] = root(e.nodes[0]);
    }
    position_.resize(model_.nodes.size());
    for (std::size_t i = 0; i < owner.size(); ++i) position_[i] = static_cast<long>(2 * root(i) + 1);
  }

  bool is_shared_joint(const Element& e) const { return is_joint(e) && !hinge_only_.count(e.nodes[1]); }

  long orientation(std::size_t node) const { return static_cast<long>(2 * node + 2); }

  void header() {
    out_ += fmt::format("# SPACAR input written by kinestat{}\n", options_.source.empty() ? "" : " from " + printable_text(options_.source));
    if (!model_.name.empty()) out_ += fmt::format("# model: {}\n", printable_text(model_.name));
    out_ += std::string(model_.has_elastic_data() ? "# Kinematic part, then stiffness and mass (ESTIFF, EM, XM; model units: "
                                                    + (model_.units.empty() ? std::string("m") : printable_text(model_.units)) +
                                                    ", N, s). "
                                                  : "# Kinematic part only. ") +
            "Node numbering as SPACAR Light: node i has position node 2i-1 and orientation\n"
            "# node 2i. Deformations not listed under RLSE or INPUTE are rigid; mark flexible ones DYNE.\n\n";
  }

  void positions() {
    out_ += "#NODES    Nn    X    Y" + std::string(planar_ ? "" : "    Z") + "\n";
    for (std::size_t i = 0; i < model_.nodes.size(); ++i) {
      if (position_[i] != static_cast<long>(2 * i + 1)) continue;  // shares a joint partner's position node
      const auto& x = model_.nodes[i].position;
      if (planar_) out_ += fmt::format("X  {:6}  {}  {}  # node {}\n", position_[i], spacar_number(x.x()), spacar_number(x.y()), printable_text(model_.nodes[i].name));
      else out_ += fmt::format("X  {:6}  {}  {}  {}  # node {}\n", position_[i], spacar_number(x.x()), spacar_number(x.y()), spacar_number(x.z()), printable_text(model_.nodes[i].name));
    }
    out_ += "\n";
  }

  void beam(long element, std::size_t p, std::size_t q, const Eigen::Vector3d& y, const std::string& comment) {
    used_orientations_.insert(p);
    used_orientations_.insert(q);
    if (planar_) {
      out_ += fmt::format("PLBEAM  {:4}  {:4} {:4}  {:4} {:4}  # {}\n", element, position_[p], orientation(p), position_[q],
                          orientation(q), comment);
    } else {
      out_ += fmt::format("BEAM  {:4}  {:4} {:4}  {:4} {:4}  {}  {}  {}  # {}\n", element, position_[p], orientation(p),
                          position_[q], orientation(q), spacar_number(y.x()), spacar_number(y.y()), spacar_number(y.z()), comment);
    }
  }

  void elements() {
    out_ += "#ELEMENTS  Ne   Xp   Rp    Xq   Rq" + std::string(planar_ ? "" : "   local y") + "\n";
    long next = 1;
    const double length = framework::characteristic_length(model_);
    for (std::size_t e = 0; e < model_.elements.size(); ++e) {
      const Element& element = model_.elements[e];
      if (is_shared_joint(element)) continue;  // expressed by the shared position node
      number_.push_back(next);
      const std::size_t p = element.nodes[0];
      if (is_joint(element) || is_offset_pin_body(element)) {
        used_orientations_.insert(p);
        out_ += fmt::format("PINBODY  {:4}  {:4} {:4}  {:4}  # {} {}\n", next++, position_[p], orientation(p),
                            position_[element.nodes[1]], is_joint(element) ? "joint" : "pin body",
                            printable_text(element.name));
      } else if (element.type == ElementType::truss) {
        out_ += fmt::format("{}  {:4}  {:4}  {:4}  # element {}\n", planar_ ? "PLTRUSS" : "TRUSS", next, position_[p],
                            position_[element.nodes[1]], printable_text(element.name));
        ++next;
      } else if (element.type == ElementType::beam) {
        beam(next++, p, element.nodes[1], element.frame.col(1), "element " + printable_text(element.name));
      } else if (const int hinge = hinge_axis(element); hinge >= 0) {
        const std::size_t q = element.nodes[1];
        used_orientations_.insert(p);
        used_orientations_.insert(q);
        if (planar_) {
          out_ += fmt::format("PLHINGE  {:4}  {:4} {:4}  # hinge {}\n", next++, orientation(p), orientation(q), printable_text(element.name));
        } else {
          const Eigen::Vector3d direction = Eigen::Matrix3d::Identity().col(hinge - 3);
          out_ += fmt::format("HINGE  {:4}  {:4} {:4}  {}  {}  {}  # hinge {} (about {})\n", next++, orientation(p),
                              orientation(q), spacar_number(direction.x()), spacar_number(direction.y()), spacar_number(direction.z()),
                              printable_text(element.name), framework::kSlotNames[static_cast<std::size_t>(hinge)]);
        }
      } else {
        for (DeformationRole role : element.roles)
          if (role != DeformationRole::fixed)
            refuse(fmt::format("rigid body '{}' has released or independent deformations; SPACAR expresses only rigid "
                               "bodies (as rigid beams), joints (a shared position node) and hinges (two nodes, relative "
                               "translations released, two of the relative rotations in the same role)", element.name));
        // A rigid body is a star of rigid beams from its reference node.
        for (std::size_t k = 1; k < element.nodes.size(); ++k) {
          const std::size_t q = element.nodes[k];
          const Eigen::Vector3d axis = model_.nodes[q].position - model_.nodes[p].position;
          if (!(axis.norm() > kCoincident * length))
            refuse(fmt::format("rigid body '{}': nodes '{}' and '{}' coincide, so no rigid beam can join them", element.name,
                               model_.nodes[p].name, model_.nodes[q].name));
          const Eigen::Vector3d x = axis.normalized();
          const Eigen::Vector3d reference = std::abs(x.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
          const Eigen::Vector3d z = (reference - reference.dot(x) * x).normalized();
          beam(next++, p, q, z.cross(x), fmt::format("rigid body {} ({} to {})", printable_text(element.name), printable_text(model_.nodes[p].name),
                                                     printable_text(model_.nodes[q].name)));
        }
      }
    }
    // SPACAR gives a node an orientation only through an element that uses it; a pin body's
    // carried node has none of its own, and the reader refuses a PINBODY onto such a node.
    for (const Element& element : model_.elements)
      if (is_offset_pin_body(element) && !used_orientations_.count(element.nodes[1]))
        refuse(fmt::format("pin body '{}': node '{}' turns freely and no beam, hinge or body uses its orientation, so SPACAR "
                           "has no orientation node for it; join it to a beam or a body, or make it a translational node",
                           element.name, model_.nodes[element.nodes[1]].name));
    out_ += "\n";
  }

  // RLSE / INPUTE for deformations, FIX / INPUTX for coordinates, of `model` (the model itself
  // or, for the proposal, only what the proposal adds).
  void roles(const FrameworkModel& model, std::string& out, const FrameworkModel* base = nullptr, const char* prefix = "") {
    std::size_t written = element_role_lines(model, out, base, prefix);
    const std::vector<std::string> lines = coordinate_role_lines(model, base, prefix);
    for (const auto& line : lines) out += line + "\n";
    written += lines.size();
    if (!base && written) out += "\n";
    // A comment also when the proposal is applied (prefix ""): the reader takes any other line as a keyword.
    if (base && written == 0) out += "# (nothing to add: the model is exactly constrained)\n";
  }

  // The RLSE and INPUTE lines of every element (with `base`: only the roles it does not have);
  // returns how many were written.
  std::size_t element_role_lines(const FrameworkModel& model, std::string& out, const FrameworkModel* base, const char* prefix) {
    std::size_t written = 0;
    for (std::size_t e = 0, n = 0; e < model.elements.size(); ++e) {
      const Element& element = model.elements[e];
      if (is_shared_joint(model_.elements[e])) continue;
      const long number = number_[n++];
      // SPACAR's deformation numbers: a hinge's 1 is its axis, 2 and 3 the rotations across it
      // (written only together); other elements number kinestat's deformations in order.
      const int axis = hinge_axis(model_.elements[e]);
      std::vector<std::vector<std::size_t>> numbered;  // SPACAR deformation -> kinestat deformations
      if (axis >= 0) {
        numbered.push_back({static_cast<std::size_t>(axis) - (planar_ ? 3 : 0)});
        if (!planar_) numbered.push_back({});
        for (std::size_t d = 3; d < element.roles.size(); ++d)
          if (d != static_cast<std::size_t>(axis)) numbered.back().push_back(d);
      } else if (element.type != ElementType::rigid_body) {
        for (std::size_t d = 0; d < element.roles.size(); ++d) numbered.push_back({d});
      }
      for (const auto& [role, keyword] : {std::pair{DeformationRole::released, "RLSE"}, std::pair{DeformationRole::independent, "INPUTE"}}) {
        std::string list;
        for (std::size_t k = 0; k < numbered.size(); ++k) {
          std::size_t matching = 0;
          for (std::size_t d : numbered[k]) {
            const bool is_new = !base || base->elements[e].roles[d] != role;
            if (element.roles[d] == role && is_new) ++matching;
          }
          if (matching == numbered[k].size()) list += k == 1 && axis >= 0 ? " 2 3" : fmt::format(" {}", k + 1);
          else if (matching > 0)
            out += fmt::format("{}# {} of one rotation across hinge {} alone cannot be written: SPACAR gives its "
                               "deformations 2 and 3 together\n", prefix, keyword, printable_text(element.name));
        }
        if (!list.empty()) {
          out += fmt::format("{}{:<7} {:4} {}  # element {}\n", prefix, keyword, number, list, printable_text(element.name));
          ++written;
        }
      }
    }
    return written;
  }

  // The FIX and INPUTX lines of every node (with `base`: only the roles it does not have).
  std::vector<std::string> coordinate_role_lines(const FrameworkModel& model, const FrameworkModel* base, const char* prefix) {
    std::vector<std::string> lines;  // joint partners share a position node: no line twice
    std::set<std::string> seen;
    const auto add = [&](std::string line) {
      if (seen.insert(line).second) lines.push_back(std::move(line));
    };
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
      const auto& node = model.nodes[i];
      for (const auto& [role, keyword] : {std::pair{CoordinateRole::fixed, "FIX"}, std::pair{CoordinateRole::independent, "INPUTX"}}) {
        // `wanted` copies the structured binding: clang 14 refuses one named inside a lambda.
        const auto has = [&, wanted = role](int s) {
          const bool is_new = !base || base->nodes[i].roles[static_cast<std::size_t>(s)] != wanted;
          return node.roles[static_cast<std::size_t>(s)] == wanted && is_new;
        };
        const std::vector<int> translations = planar_ ? std::vector<int>{0, 1} : std::vector<int>{0, 1, 2};
        std::vector<int> chosen;
        for (int s : translations)
          if (has(s)) chosen.push_back(s);
        if (chosen.size() == translations.size() && role == CoordinateRole::fixed) {
          add(fmt::format("{}FIX     {:4}       # node {} position", prefix, position_[i], printable_text(node.name)));
        } else {
          for (int s : chosen)
            add(fmt::format("{}{:<7} {:4}  {}    # node {} {}", prefix, keyword, position_[i], s + 1, printable_text(node.name),
                                     framework::kSlotNames[static_cast<std::size_t>(s)]));
        }
        if (!node.rotational || !used_orientations_.count(i)) continue;
        // Spatial orientation nodes hold Euler parameters λ0..λ3; λ1, λ2, λ3 are numbers 2, 3, 4.
        const std::vector<int> rotations = planar_ ? std::vector<int>{5} : std::vector<int>{3, 4, 5};
        chosen.clear();
        for (int s : rotations)
          if (has(s)) chosen.push_back(s);
        if (chosen.size() == rotations.size() && role == CoordinateRole::fixed) {
          add(fmt::format("{}FIX     {:4}       # node {} orientation", prefix, orientation(i), printable_text(node.name)));
        } else {
          for (int s : chosen)
            add(fmt::format("{}{:<7} {:4}  {}    # node {} {}", prefix, keyword, orientation(i), planar_ ? 1 : s - 1,
                                     printable_text(node.name), framework::kSlotNames[static_cast<std::size_t>(s)]));
        }
      }
    }
    return lines;
  }

  void proposal() {
    if (options_.apply_proposal) {
      out_ += "# kinestat's proposal for exact constraint (applied):\n";
      roles(*options_.proposed, out_, &model_, "");
    } else {
      out_ += "# kinestat's proposal for exact constraint: remove the '# ' and paste these lines above END\n";
      roles(*options_.proposed, out_, &model_, "# ");
    }
  }

  const FrameworkModel& model_;
  const SpacarWriteOptions& options_;
  bool planar_ = false;
  std::string out_;
  std::vector<long> position_;
  std::vector<long> number_;  // SPACAR number of each written kinestat element
  std::set<std::size_t> used_orientations_;
  std::set<std::size_t> hinge_only_;  // nodes whose orientation only hinges use
};

}  // namespace

std::string spacar_text(const FrameworkModel& model, const SpacarWriteOptions& options) {
  return SpacarWriter(model, options).write();
}

}  // namespace kinestat::io
