// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/urdf_reader.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>

#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <set>
#include <string_view>
#include <vector>

#include "kinestat/io/text_file.hpp"

#if KINESTAT_HAVE_TINYXML2
#include <tinyxml2.h>
#endif

namespace kinestat::io {

#if KINESTAT_HAVE_TINYXML2

namespace {

using tinyxml2::XMLElement;

/// A rigid transform: x_world = rotation * x_local + origin.
struct Frame {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Frame then(const Frame& local) const { return {rotation * local.rotation, rotation * local.origin + origin}; }
};

struct UrdfJoint {
  const XMLElement* element = nullptr;
  std::string name, type, parent, child;
  Frame origin;  ///< joint frame relative to the parent link frame (to the child's for a <gazebo> joint)
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
  bool loop = false;  ///< closes a loop (its child already has a parent, a <loop_joint> or a <gazebo> joint)
  bool on_child = false;  ///< `origin` is in the child link's frame (SDFormat's joint pose, in <gazebo>)
};

class UrdfReader {
 public:
  UrdfReader(std::string path, const std::string& text, const ImportOptions& options)
      : path_(std::move(path)), text_(text), lines_(text_), options_(options) {}

  ImportedNetwork read() {
    tinyxml2::XMLDocument document;
    if (document.Parse(text_.data(), text_.size()) != tinyxml2::XML_SUCCESS)
      throw InputError({path_, document.ErrorLineNum(), 1}, fmt::format("malformed XML: {}", document.ErrorStr()));
    const XMLElement* robot = document.RootElement();
    if (!robot || std::string(robot->Name()) != "robot")
      throw InputError({path_, robot ? robot->GetLineNum() : 1, 1}, "a URDF file has a <robot> root element");
    NetworkBuilder builder(path_, attribute_or(robot, "name", ""), "m");  // URDF lengths are metres
    std::set<std::string> ignored;
    for (const XMLElement* e = robot->FirstChildElement(); e; e = e->NextSiblingElement()) {
      const std::string tag = e->Name();
      if (tag == "link") read_link(e);
      else if (tag == "joint" || tag == "drake:joint") joints_.push_back(read_joint(e, false));  // Drake: ball, universal, planar
      else if (tag == "loop_joint") joints_.push_back(read_loop_joint(e));
      else if (tag == "transmission") transmissions_.push_back(attribute_or(e, "name", "(unnamed)"));
      else if (tag == "gazebo" && e->FirstChildElement("joint")) read_gazebo_joints(e);
      else ignored.insert(tag);
    }
    // Drake's dialect: a joint may name the world without a <link name="world">; it is then
    // the root, the ground.
    bool implicit_world = false;
    if (!links_.count("world"))
      for (const UrdfJoint& j : joints_)
        if (j.parent == "world") {
          links_.emplace("world", robot);
          link_order_.insert(link_order_.begin(), "world");
          implicit_world = true;
          break;
        }
    if (links_.empty()) fail(robot, "the robot has no <link>");
    for (const UrdfJoint& j : joints_)
      for (const std::string* link : {&j.parent, &j.child})
        if (!links_.count(*link)) fail(j.element, fmt::format("joint '{}' names link '{}', which is not a <link> of the robot", j.name, *link));
    build_tree();
    for (const std::string& name : link_order_) builder.body(name);
    builder.set_ground(root_);
    for (const UrdfJoint& j : joints_) couple(builder, j);
    ImportedNetwork out;
    out.notices.push_back(fmt::format("{}: note: lengths in metres; joint limits, dynamics, inertia and geometry are not read "
                                      "(no kinematic meaning)", path_));
    if (options_.base == ImportOptions::Base::floating) {
      builder.float_base(root_, where(links_.at(root_)));
      out.notices.push_back(fmt::format("{}: note: base: the root link '{}' floats (a free coupling to the world), as --base "
                                        "floating asks", path_, root_));
    } else {
      out.notices.push_back(fmt::format("{}: note: base: the root link '{}' is the ground (URDF's convention for a fixed-base "
                                        "robot; --base floating lets it float, as a legged or mobile robot does)", path_, root_));
    }
    if (std::string loose = builder.mount_loose_groups(options_.base == ImportOptions::Base::fixed); !loose.empty())
      out.notices.push_back(std::move(loose));
    out.loaded = builder.finish();
    if (!mimics_.empty())
      out.notices.push_back(fmt::format("{}: note: mimic joint(s) {} read as independent joints: a mimic relation is a "
                                        "control law, not a constraint of the mechanism", path_, mimics_));
    if (!transmissions_.empty()) {
      std::string names;
      for (const auto& t : transmissions_) names += (names.empty() ? "" : ", ") + t;
      out.notices.push_back(fmt::format("{}: note: transmission(s) {} ignored (actuation, not kinematics)", path_, names));
    }
    if (implicit_world)
      out.notices.push_back(fmt::format("{}: note: a joint names the link 'world', which the file does not declare: read as "
                                        "the ground, as Drake does", path_));
    if (gazebo_joints_ > 0)
      out.notices.push_back(fmt::format("{}: note: {} joint(s) in <gazebo> blocks read as loop-closing couplings (their pose "
                                        "in the child link's frame, as Gazebo reads them)", path_, gazebo_joints_));
    if (!ignored.empty()) {
      std::string names;
      for (const auto& t : ignored) names += (names.empty() ? "<" : ", <") + t + ">";
      out.notices.push_back(fmt::format("{}: note: ignored elements without kinematic meaning: {}", path_, names));
    }
    return out;
  }

 private:
  // tinyxml2 knows lines only; the column is that of the element's '<' on its line.
  SourceLocation where(const tinyxml2::XMLNode* node) const {
    const int line = node->GetLineNum();
    int column = 1;
    if (const XMLElement* e = node->ToElement()) {
      const std::string_view text = lines_.line(line);
      const std::size_t at = text.find(std::string("<") + e->Name());
      if (at != std::string_view::npos) column = static_cast<int>(at) + 1;
    }
    return {path_, line, column};
  }

  [[noreturn]] void fail(const tinyxml2::XMLNode* at, const std::string& problem) const { throw InputError(where(at), problem); }

  static std::string attribute_or(const XMLElement* e, const char* name, const std::string& fallback) {
    const char* value = e->Attribute(name);
    return value ? value : fallback;
  }

  std::string required(const XMLElement* e, const char* name) const {
    const char* value = e->Attribute(name);
    if (!value || !*value) fail(e, fmt::format("<{}> needs a '{}' attribute", e->Name(), name));
    return value;
  }

  const XMLElement* required_child(const XMLElement* e, const char* name, const std::string& what) const {
    const XMLElement* child = e->FirstChildElement(name);
    if (!child) fail(e, fmt::format("{} needs a <{}> element", what, name));
    return child;
  }

  Eigen::Vector3d vector(const XMLElement* e, const char* name, const Eigen::Vector3d& fallback) const {
    const char* value = e->Attribute(name);
    if (!value) return fallback;
    Eigen::Vector3d v;
    const char* p = value;
    const char* end = value + std::char_traits<char>::length(value);
    for (int i = 0; i < 3; ++i) {
      while (p < end && (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r')) ++p;
      double x = 0;
      const auto [next, ec] = std::from_chars(p, end, x);
      if (ec != std::errc() || !std::isfinite(x))
        fail(e, fmt::format("attribute {}=\"{}\" of <{}> must be three finite numbers", name, value, e->Name()));
      v(i) = x;
      p = next;
    }
    while (p < end && (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r')) ++p;
    if (p != end) fail(e, fmt::format("attribute {}=\"{}\" of <{}> must be three finite numbers", name, value, e->Name()));
    return v;
  }

  // URDF's origin: translation xyz, then fixed-axis roll, pitch, yaw: R = Rz(y) Ry(p) Rx(r).
  Frame frame(const XMLElement* e) const {
    Frame f;
    if (!e) return f;
    const Eigen::Vector3d rpy = vector(e, "rpy", Eigen::Vector3d::Zero());
    f.rotation = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
                     .toRotationMatrix();
    f.origin = vector(e, "xyz", Eigen::Vector3d::Zero());
    return f;
  }

  void read_link(const XMLElement* e) {
    const std::string name = required(e, "name");
    if (!links_.emplace(name, e).second) fail(e, fmt::format("duplicate link name '{}'", name));
    link_order_.push_back(name);
  }

  UrdfJoint read_joint(const XMLElement* e, bool loop) {
    UrdfJoint j;
    j.element = e;
    j.loop = loop;
    j.name = required(e, "name");
    j.type = required(e, "type");
    j.parent = required(required_child(e, "parent", fmt::format("joint '{}'", j.name)), "link");
    j.child = required(required_child(e, "child", fmt::format("joint '{}'", j.name)), "link");
    j.origin = frame(e->FirstChildElement("origin"));
    if (const XMLElement* axis = e->FirstChildElement("axis")) j.axis = vector(axis, "xyz", Eigen::Vector3d::UnitX());
    if (e->FirstChildElement("mimic")) mimics_ += (mimics_.empty() ? "" : ", ") + j.name;
    return j;
  }

  // Drake's loop joint: <link1 link= xyz= rpy=/> gives the joint frame on the first link,
  // <link2 .../> the same frame on the second (not needed: the mechanism is assembled).
  UrdfJoint read_loop_joint(const XMLElement* e) {
    UrdfJoint j;
    j.element = e;
    j.loop = true;
    j.name = required(e, "name");
    j.type = required(e, "type");
    const XMLElement* link1 = required_child(e, "link1", fmt::format("loop joint '{}'", j.name));
    const XMLElement* link2 = required_child(e, "link2", fmt::format("loop joint '{}'", j.name));
    j.parent = required(link1, "link");
    j.child = required(link2, "link");
    j.origin = frame(link1);
    if (const XMLElement* axis = e->FirstChildElement("axis")) j.axis = vector(axis, "xyz", Eigen::Vector3d::UnitX());
    return j;
  }

  // Gazebo's way of closing a loop in URDF (its tutorial's four-bar): an SDFormat joint inside a
  // <gazebo> block, <parent> and <child> link names as text, <pose> (x y z roll pitch yaw) in
  // the child link's frame and <axis><xyz> in the joint frame, as SDFormat 1.6 reads them.
  void read_gazebo_joints(const XMLElement* gazebo) {
    for (const XMLElement* e = gazebo->FirstChildElement("joint"); e; e = e->NextSiblingElement("joint")) {
      UrdfJoint j;
      j.element = e;
      j.loop = true;
      j.on_child = true;
      j.name = required(e, "name");
      j.type = required(e, "type");
      j.parent = text_of(required_child(e, "parent", fmt::format("joint '{}'", j.name)));
      j.child = text_of(required_child(e, "child", fmt::format("joint '{}'", j.name)));
      if (const XMLElement* pose = e->FirstChildElement("pose")) {
        const std::vector<double> v = numbers(pose, 6);
        const Eigen::Vector3d rpy(v[3], v[4], v[5]);
        j.origin.rotation = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
        j.origin.origin = Eigen::Vector3d(v[0], v[1], v[2]);
      }
      if (const XMLElement* axis = e->FirstChildElement("axis"))
        if (const XMLElement* xyz = axis->FirstChildElement("xyz")) {
          const std::vector<double> v = numbers(xyz, 3);
          j.axis = Eigen::Vector3d(v[0], v[1], v[2]);
        }
      if (j.type == "continuous") j.type = "revolute";
      joints_.push_back(std::move(j));
      ++gazebo_joints_;
    }
  }

  std::string text_of(const XMLElement* e) const {
    const char* text = e->GetText();
    std::string_view value = text ? text : "";
    while (!value.empty() && std::isspace(static_cast<unsigned char>(value.front()))) value.remove_prefix(1);
    while (!value.empty() && std::isspace(static_cast<unsigned char>(value.back()))) value.remove_suffix(1);
    if (value.empty()) fail(e, fmt::format("<{}> needs a link name", e->Name()));
    return std::string(value);
  }

  // Exactly `count` finite numbers, the text of `e`.
  std::vector<double> numbers(const XMLElement* e, std::size_t count) const {
    const char* text = e->GetText() ? e->GetText() : "";
    const char* p = text;
    const char* end = text + std::char_traits<char>::length(text);
    std::vector<double> out;
    while (true) {
      while (p < end && std::isspace(static_cast<unsigned char>(*p))) ++p;
      if (p == end) break;
      double x = 0;
      const auto [next, ec] = std::from_chars(p, end, x);
      if (ec != std::errc() || !std::isfinite(x) || out.size() == count)
        fail(e, fmt::format("<{}> must hold {} finite numbers", e->Name(), count));
      out.push_back(x);
      p = next;
    }
    if (out.size() != count) fail(e, fmt::format("<{}> must hold {} finite numbers", e->Name(), count));
    return out;
  }

  // In file order, the first joint that names a link as child is its tree joint; any later
  // one closes a loop. The root is the one link that is nobody's child.
  void build_tree() {
    std::map<std::string, std::size_t> tree_joint;
    for (std::size_t k = 0; k < joints_.size(); ++k) {
      UrdfJoint& j = joints_[k];
      if (j.loop) continue;
      if (!tree_joint.emplace(j.child, k).second) j.loop = true;
    }
    std::vector<std::string> roots;
    for (const std::string& name : link_order_)
      if (!tree_joint.count(name)) roots.push_back(name);
    if (roots.empty()) fail(joints_.front().element, "every link is the child of a joint: the tree has no root link (the ground)");
    // The first root is the robot's base; a later one is a loose link (or the base of a loose
    // group), placed at the base's frame, as URDF gives it no pose: the builder mounts it.
    root_ = roots[0];
    for (const std::string& root : roots) frames_[root] = Frame{};
    // Resolve frames from the roots down, breadth first: each tree joint once.
    std::map<std::string, std::vector<std::size_t>> children;
    for (const auto& [child, k] : tree_joint) children[joints_[k].parent].push_back(k);
    std::vector<std::string> queue = roots;
    for (std::size_t next = 0; next < queue.size(); ++next) {
      const auto found = children.find(queue[next]);
      if (found == children.end()) continue;
      const Frame parent = frames_.at(queue[next]);
      for (const std::size_t k : found->second) {
        const UrdfJoint& j = joints_[k];
        frames_[j.child] = parent.then(j.origin);
        queue.push_back(j.child);
      }
    }
    for (const auto& [child, k] : tree_joint)
      if (!frames_.count(child))
        fail(joints_[k].element, fmt::format("link '{}' is not connected to the root link '{}' by the tree of joints", child, root_));
  }

  void couple(NetworkBuilder& builder, const UrdfJoint& j) const {
    const Frame joint = frames_.at(j.on_child ? j.child : j.parent).then(j.origin);
    JointGeometry g;
    g.point = joint.origin;
    const Eigen::Vector3d axis = joint.rotation * j.axis;
    screw::CouplingType type;
    if (j.type == "revolute" || j.type == "continuous") {
      type = screw::CouplingType::revolute;
      g.axis = axis;
    } else if (j.type == "prismatic") {
      type = screw::CouplingType::prismatic;
      g.axis = axis;
    } else if (j.type == "fixed") {
      type = screw::CouplingType::rigid;
    } else if (j.type == "floating") {
      type = screw::CouplingType::free;
    } else if (j.type == "planar") {
      type = screw::CouplingType::planar;
      g.normal = axis;
    } else if (j.type == "ball" || j.type == "spherical") {
      type = screw::CouplingType::spherical;
    } else if (j.type == "universal") {
      // Drake's universal joint: rotations about the joint frame's x and y axes.
      type = screw::CouplingType::universal;
      g.axis = joint.rotation.col(0);
      g.axis2 = joint.rotation.col(1);
    } else {
      fail(j.element, fmt::format("joint '{}' has unknown type '{}'; expected revolute, continuous, prismatic, fixed, floating, "
                                  "planar, ball or universal", j.name, j.type));
    }
    builder.couple(j.name, type, j.parent, j.child, g, where(j.element));
  }

  std::string path_;
  const std::string& text_;
  LineIndex lines_;  // built once: every joint is located (linear time in the joints)
  ImportOptions options_;
  std::map<std::string, const XMLElement*> links_;
  std::vector<std::string> link_order_;  // bodies in file order
  std::vector<UrdfJoint> joints_;
  std::map<std::string, Frame> frames_;
  std::string root_;
  std::string mimics_;
  std::vector<std::string> transmissions_;
  int gazebo_joints_ = 0;
};

}  // namespace

bool urdf_reader_built_in() { return true; }

ImportedNetwork parse_urdf(const std::string& path, const std::string& text, const ImportOptions& options) {
  return UrdfReader(path, text, options).read();
}

#else

bool urdf_reader_built_in() { return false; }

ImportedNetwork parse_urdf(const std::string& path, const std::string&, const ImportOptions&) {
  throw InputError({path, 0, 0}, "URDF is not built in: rebuild kinestat with libtinyxml2-dev installed (docs/formats.md)");
}

#endif

ImportedNetwork read_urdf(const std::string& path, const ImportOptions& options) {
  return parse_urdf(path, read_text_file(path, options.max_input_bytes), options);
}

}  // namespace kinestat::io
