// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/mjcf_reader.hpp"

#include <fmt/format.h>

#include "kinestat/io/text_file.hpp"

#if KINESTAT_HAVE_MUJOCO && KINESTAT_HAVE_TINYXML2
#include <mujoco/mujoco.h>
#include <tinyxml2.h>

#include <Eigen/Geometry>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <mutex>
#include <numbers>
#include <optional>
#include <set>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "kinestat/io/printable_text.hpp"
#endif

namespace kinestat::io {

#if KINESTAT_HAVE_MUJOCO && KINESTAT_HAVE_TINYXML2

namespace {

/// The digits of `text` from `at` on (at most `most`), as read by MuJoCo's "line N".
std::size_t digits_at(const std::string& text, std::size_t at, std::size_t most) {
  std::size_t n = 0;
  while (at + n < text.size() && n < most && std::isdigit(static_cast<unsigned char>(text[at + n]))) ++n;
  return n;
}

/// The first "line N" of a MuJoCo message (N of at most 9 digits), 0 when there is none.
/// Hand-written rather than <regex>: std::regex cost this file 20 s of compile time.
int mujoco_message_line(const std::string& message) {
  for (std::size_t at = message.find("line "); at != std::string::npos; at = message.find("line ", at + 1)) {
    const std::size_t n = digits_at(message, at + 5, 9);
    if (n > 0) return std::stoi(message.substr(at + 5, n));
  }
  return 0;
}

/// `message` without its ", line N" and ", column M" places (the line is reported apart).
std::string without_mujoco_places(const std::string& message) {
  std::string out;
  std::size_t copied = 0;
  for (std::size_t at = message.find("line "); at != std::string::npos; at = message.find("line ", at + 1)) {
    const std::size_t n = digits_at(message, at + 5, std::string::npos);
    if (n == 0 || at < copied) continue;
    std::size_t begin = at;
    if (begin > copied && message[begin - 1] == ' ') --begin;
    if (begin > copied && message[begin - 1] == ',') --begin;
    std::size_t end = at + 5 + n;
    if (message.compare(end, 9, ", column ") == 0) {
      const std::size_t m = digits_at(message, end + 9, std::string::npos);
      if (m > 0) end += 9 + m;
    }
    out.append(message, copied, begin - copied);
    copied = end;
    at = end - 1;
  }
  return out.append(message, copied, std::string::npos);
}


struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
struct VfsDeleter {
  void operator()(mjVFS* v) const {
    mj_deleteVFS(v);
    delete v;
  }
};

/// MuJoCo's default warning handler prints to standard output and appends to MUJOCO_LOG.TXT
/// in the working directory; kinestat collects the warnings as notices instead, into the
/// reader of the one load in progress (guarded by load_mutex).
std::vector<std::string>* warnings = nullptr;
std::mutex load_mutex;
void collect_warning(const char* message) {
  if (warnings && warnings->size() < 16) warnings->push_back(message);
}

/// Largest mjData a model may ask for (stack plus buffer): mj_makeData ends the process when
/// an allocation fails, so a model asking for more is refused first.
constexpr double kMaxDataBytes = 1 << 30;

// MuJoCo 2.2.2's compiler takes time growing faster than the number of bodies (a flat model of
// 10^4 hinged bodies: 2.4 s; 2 * 10^4: 13 s; 10^5: 131 s), so larger models are refused before it
// starts.
constexpr std::size_t kMaxMjcfBodies = 10000;

// Attributes that hold numbers MuJoCo reads as doubles: "nan" or "inf" in one of them is
// refused where it is written (MuJoCo 2.2.2 takes pos="nan" and puts the joint at the origin).
bool numeric_attribute(std::string_view name) {
  for (const char* numeric : {"pos", "quat", "axisangle", "xyaxes", "zaxis", "euler", "axis", "anchor", "fromto", "size", "range",
                              "ref", "springref", "relpose", "data", "polycoef", "torquescale", "mass", "diaginertia",
                              "fullinertia", "ipos", "iquat", "stiffness", "damping", "armature", "frictionloss", "margin",
                              "gap", "solref", "solimp", "solreflimit", "solimplimit", "solreffriction", "solimpfriction",
                              "friction", "springdamper", "gear", "lengthrange", "ctrlrange", "forcerange", "density", "scale"})
    if (name == numeric) return true;
  return false;
}

// Assets that point to files (meshes, textures, heightfields, skins) and materials (which
// use textures): none has kinematic meaning, so none is ever read (issue 37).
bool file_asset(std::string_view name) {
  return name == "mesh" || name == "texture" || name == "hfield" || name == "skin" || name == "material";
}

/// An element of the document MuJoCo compiles, and where the user wrote it.
struct Origin {
  std::string file;
  int line = 0;
  int depth = 0;   ///< includes between the file given and this element's file
  int column = 0;  ///< of the element's '<' on its line (0: not known)
};

/// A file of the document, indexed by line, so an element's column can be found on its line
/// (tinyxml2 keeps lines only).
struct FileText {
  explicit FileText(std::string content) : text(std::move(content)), lines(text) {}
  std::string text;
  LineIndex lines;
};

/// The MJCF document as kinestat hands it to MuJoCo: every <include file=> expanded in place
/// (resolved as MuJoCo does, in the folder of the file given; each file once), numbers checked,
/// and every asset that needs a file stripped (mesh geoms become small spheres: a geom has no
/// kinematic meaning). Printed once; every line of the printed text and every name maps back to
/// the file and line the user wrote, so MuJoCo's messages and the joints point there.
class MjcfDocument {
 public:
  MjcfDocument(std::string path, const ImportOptions& options, bool folder_known)
      : path_(std::move(path)), options_(options), folder_known_(folder_known) {}

  /// Builds the document from the text of the file given. Throws InputError where a problem is.
  void build(const std::string& text) {
    if (folder_known_) {
      std::error_code error;
      const auto canonical = std::filesystem::weakly_canonical(path_, error);
      folder_ = (error ? std::filesystem::path(path_) : canonical).parent_path().string();
      included_.insert(error ? path_ : canonical.string());
    }
    total_bytes_ = text.size();
    texts_.emplace(path_, std::make_unique<FileText>(text));
    if (document_.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS)
      throw InputError({path_, document_.ErrorLineNum(), 1}, fmt::format("malformed XML: {}", printable_text(document_.ErrorStr())));
    tinyxml2::XMLElement* root = document_.RootElement();
    if (!root || std::string_view(root->Name()) != "mujoco")
      throw InputError({path_, root ? root->GetLineNum() : 1, 1}, "expected an MJCF model: a <mujoco> root element");
    std::vector<tinyxml2::XMLElement*> stack{root};
    std::size_t bodies = 0, stripped = 0;
    std::vector<tinyxml2::XMLElement*> removed;
    while (!stack.empty()) {
      tinyxml2::XMLElement* e = stack.back();
      stack.pop_back();
      const std::string_view name = e->Name();
      if (name == "include") {
        for (tinyxml2::XMLElement* spliced : expand(e)) stack.push_back(spliced);
        continue;
      }
      check_numbers(e);
      if (name == "body") ++bodies;
      if (name == "site")
        if (const char* site = e->Attribute("name")) sites_.emplace(site, e);
      const tinyxml2::XMLElement* parent = e->Parent() ? e->Parent()->ToElement() : nullptr;
      if (file_asset(name) && parent && std::string_view(parent->Name()) == "asset") {
        removed.push_back(e);
        ++stripped;
        continue;
      }
      if (name == "skin") {  // MuJoCo 2.2.2 keeps skins in <deformable> too
        removed.push_back(e);
        ++stripped;
        continue;
      }
      strip_geometry(e);
      for (tinyxml2::XMLElement* child = e->LastChildElement(); child; child = child->PreviousSiblingElement()) stack.push_back(child);
    }
    if (bodies > kMaxMjcfBodies)
      throw InputError({path_, 0, 0}, fmt::format("the model has {} <body> elements; kinestat reads at most {} from an MJCF file, "
                                                  "because MuJoCo 2.2.2's compiler takes time growing faster than their number "
                                                  "(convert the model to URDF, which is read without this limit)",
                                                  bodies, kMaxMjcfBodies));
    for (tinyxml2::XMLElement* e : removed) e->Parent()->DeleteChild(e);
    if (stripped > 0)
      notices.push_back(fmt::format("{}: note: ignored {} mesh, texture, heightfield, skin and material asset(s), and mesh geoms "
                                    "read as small spheres: geometry has no kinematic meaning, so no asset file is read",
                                    path_, stripped));
    strip_dynamics(root);
    read_compiler(root);
    flatten_frames(root);
    connect_sites(root);
    read_welds(root);
    print();
  }

  /// The text MuJoCo compiles.
  const std::string& text() const { return printed_; }

  /// Where line `line` of the printed text was written (0: the file given, no line).
  SourceLocation at_printed_line(int line) const {
    if (line <= 0 || printed_lines_.empty()) return {path_, 0, 0};
    const Origin& o = printed_lines_[std::min<std::size_t>(static_cast<std::size_t>(line), printed_lines_.size() - 1)];
    return {o.file.empty() ? path_ : o.file, o.line, o.line > 0 ? 1 : 0};
  }

  /// Where the first element named `name` was written.
  SourceLocation where_named(const std::string& name) const {
    const auto found = named_.find(name);
    if (found == named_.end()) return {path_, 0, 0};
    return {found->second.file, found->second.line, found->second.column};
  }

  /// For each equality constraint (MuJoCo's order): a weld with torquescale 0, which constrains
  /// the position of a point only and so is a connect (MuJoCo's reference).
  std::vector<bool> weld_as_connect;
  std::vector<std::string> notices;

 private:
  Origin origin(const tinyxml2::XMLElement* e) const {
    const auto found = origins_.find(e);
    return found != origins_.end() ? found->second : Origin{path_, e->GetLineNum(), 0};
  }

  SourceLocation where(const tinyxml2::XMLElement* e) const {
    const Origin o = origin(e);
    return {o.file, o.line, o.line > 0 ? column_of(o, e->Name()) : 0};
  }

  // The column of `<tag` on the element's line: the first on the line (1 when not found).
  int column_of(const Origin& o, std::string_view tag) const {
    const auto found = texts_.find(o.file);
    if (found == texts_.end() || o.line <= 0) return 1;
    const std::string_view line = found->second->lines.line(o.line);
    const std::size_t at = line.find("<" + std::string(tag));
    return at == std::string_view::npos ? 1 : static_cast<int>(at) + 1;
  }

  void check_numbers(const tinyxml2::XMLElement* e) const {
    for (const tinyxml2::XMLAttribute* a = e->FirstAttribute(); a; a = a->Next()) {
      if (!numeric_attribute(a->Name())) continue;
      const char* p = a->Value();
      while (*p) {
        char* end = nullptr;
        const double x = std::strtod(p, &end);
        if (end == p) break;  // not a number: MuJoCo says so
        if (!std::isfinite(x))
          throw InputError(where(e), fmt::format("attribute {}=\"{}\" of <{}>: every number must be finite", a->Name(),
                                                 printable_text(std::string_view(a->Value()).substr(0, 60)), e->Name()));
        p = end;
      }
    }
  }

  // A geom that shows a mesh or a heightfield becomes a small sphere (in <default> classes too),
  // and materials are dropped everywhere: what they name is stripped.
  static void strip_geometry(tinyxml2::XMLElement* e) {
    e->DeleteAttribute("material");
    if (std::string_view(e->Name()) != "geom") return;
    const char* type = e->Attribute("type");
    const bool shaped = e->Attribute("mesh") || e->Attribute("hfield") ||
                        (type && (std::string_view(type) == "mesh" || std::string_view(type) == "hfield" || std::string_view(type) == "sdf"));
    if (!shaped) return;
    e->DeleteAttribute("mesh");
    e->DeleteAttribute("hfield");
    e->DeleteAttribute("fromto");
    e->SetAttribute("type", "sphere");
    e->SetAttribute("size", "0.01");
  }

  // <include file="..."/> -> the children of the included file's <mujoco>, in its place.
  std::vector<tinyxml2::XMLElement*> expand(tinyxml2::XMLElement* include) {
    const SourceLocation at = where(include);
    const int depth = origin(include).depth + 1;
    const char* written_c = include->Attribute("file");
    if (!written_c || !*written_c) throw InputError(at, "<include> needs a 'file' attribute");
    const std::string written = written_c;
    if (!folder_known_) throw InputError(at, "an <include> is resolved in the model's folder: read the model from its file, not from text");
    if (depth > kMaxIncludeDepth)
      throw InputError(at, fmt::format("includes nested more than {} files deep; kinestat stops there", kMaxIncludeDepth));
    // MuJoCo resolves an include in the folder of the file given, whichever file holds it.
    const std::filesystem::path target = std::filesystem::path(written).is_absolute() ? std::filesystem::path(written)
                                                                                      : std::filesystem::path(folder_) / written;
    std::error_code error;
    if (!std::filesystem::exists(target, error))
      throw InputError(at, fmt::format("the included file '{}' is not found in the model's folder (looked for {}); kinestat never "
                                       "looks in the working directory", printable_text(written),
                                       printable_text(target.lexically_normal().string())));
    const std::string canonical = allowed_include(target.string(), folder_, options_, at, written);
    if (!included_.insert(canonical).second)
      throw InputError(at, fmt::format("'{}' is {}, which is already included: MuJoCo includes a file once (a file that includes "
                                       "itself never ends)", printable_text(written), printable_text(canonical)));
    const std::string& text = texts_.emplace(canonical, std::make_unique<FileText>(read_text_file(canonical, options_.max_input_bytes))).first->second->text;
    total_bytes_ += text.size();
    if (total_bytes_ > options_.max_input_bytes)
      throw InputError(at, fmt::format("with its includes the model is larger than the {} limit on model files (--max-input-size)",
                                       size_text(options_.max_input_bytes)));
    tinyxml2::XMLDocument& part = *parts_.emplace_back(std::make_unique<tinyxml2::XMLDocument>());
    if (part.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS)
      throw InputError({canonical, part.ErrorLineNum(), 1}, fmt::format("malformed XML: {}", printable_text(part.ErrorStr())));
    const tinyxml2::XMLElement* root = part.RootElement();
    if (!root || std::string_view(root->Name()) != "mujoco")
      throw InputError({canonical, root ? root->GetLineNum() : 1, 1}, "an included MJCF file has a <mujoco> root element");
    // Clones of the included elements, each remembered with its own file and line.
    tinyxml2::XMLNode* parent = include->Parent();
    tinyxml2::XMLNode* after = include;
    std::vector<tinyxml2::XMLElement*> spliced;
    for (const tinyxml2::XMLElement* child = root->FirstChildElement(); child; child = child->NextSiblingElement()) {
      tinyxml2::XMLElement* copy = clone(child, canonical, depth);
      parent->InsertAfterChild(after, copy);
      after = copy;
      spliced.push_back(copy);
    }
    parent->DeleteChild(include);
    return spliced;
  }

  tinyxml2::XMLElement* clone(const tinyxml2::XMLElement* source, const std::string& file, int depth) {
    tinyxml2::XMLElement* top = source->ShallowClone(&document_)->ToElement();
    std::vector<std::pair<const tinyxml2::XMLNode*, tinyxml2::XMLNode*>> stack{{source, top}};
    while (!stack.empty()) {
      const auto [from, to] = stack.back();
      stack.pop_back();
      if (from->ToElement()) origins_[to->ToElement()] = {file, from->GetLineNum(), depth};
      for (const tinyxml2::XMLNode* child = from->FirstChild(); child; child = child->NextSibling()) {
        if (child->ToComment()) continue;
        tinyxml2::XMLNode* copy = child->ShallowClone(&document_);
        to->InsertEndChild(copy);
        stack.push_back({child, copy});
      }
    }
    return top;
  }

  // Elements MuJoCo 3 files fill with options that MuJoCo 2.2.2 refuses ("implicitfast",
  // actuatorfrcrange, assetdir, ...) and that have no kinematic meaning: removed before MuJoCo
  // compiles, with one note. Tendons stay: equalities may name them (and are then ignored).
  void strip_dynamics(tinyxml2::XMLElement* root) {
    std::set<std::string> names;
    for (tinyxml2::XMLElement* e = root->FirstChildElement(); e;) {
      tinyxml2::XMLElement* next = e->NextSiblingElement();
      const std::string_view tag = e->Name();
      if (tag == "option" || tag == "actuator" || tag == "sensor" || tag == "keyframe" || tag == "contact" || tag == "visual" ||
          tag == "statistic" || tag == "custom" || tag == "extension") {
        names.insert("<" + std::string(tag) + ">");
        root->DeleteChild(e);
      } else if (tag == "compiler") {
        for (const char* dir : {"assetdir", "meshdir", "texturedir"}) e->DeleteAttribute(dir);
      }
      e = next;
    }
    // Joint attributes of actuation (MuJoCo 3: actuatorfrcrange, actuatorfrclimited,
    // actuatorgravcomp), in bodies and in default classes.
    std::vector<tinyxml2::XMLElement*> stack{root};
    while (!stack.empty()) {
      tinyxml2::XMLElement* e = stack.back();
      stack.pop_back();
      if (std::string_view(e->Name()) == "joint")
        for (const char* a : {"actuatorfrcrange", "actuatorfrclimited", "actuatorgravcomp"})
          if (e->Attribute(a)) {
            names.insert(std::string("joint ") + a);
            e->DeleteAttribute(a);
          }
      for (tinyxml2::XMLElement* child = e->FirstChildElement(); child; child = child->NextSiblingElement()) stack.push_back(child);
    }
    if (!names.empty()) {
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      notices.push_back(fmt::format("{}: note: ignored {} (actuation, sensing, contact, simulation options: no kinematic "
                                    "meaning; removed before MuJoCo compiles the model)", path_, list));
    }
  }

  // The compiler's angle unit and Euler sequence, which <frame> orientations are written in.
  void read_compiler(const tinyxml2::XMLElement* root) {
    for (const tinyxml2::XMLElement* c = root->FirstChildElement("compiler"); c; c = c->NextSiblingElement("compiler")) {
      if (const char* angle = c->Attribute("angle")) degrees_ = std::string_view(angle) != "radian";
      if (const char* seq = c->Attribute("eulerseq")) euler_sequence_ = seq;
    }
  }

  // The numbers of attribute `name` of `e` (exactly `count` of them), or nothing when absent.
  std::optional<std::vector<double>> numbers(const tinyxml2::XMLElement* e, const char* name, std::size_t count) const {
    const char* text = e->Attribute(name);
    if (!text) return std::nullopt;
    std::vector<double> out;
    for (const char* p = text;;) {
      char* end = nullptr;
      const double x = std::strtod(p, &end);
      if (end == p) break;
      out.push_back(x);
      p = end;
    }
    if (out.size() != count)
      throw InputError(where(e), fmt::format("attribute {}=\"{}\" of <{}> must hold {} numbers", name,
                                             printable_text(std::string_view(text).substr(0, 60)), e->Name(), count));
    return out;
  }

  // The orientation an element writes (quat, axisangle, euler, xyaxes or zaxis), as MuJoCo
  // reads it (angles in the compiler's unit, Euler angles in its sequence).
  Eigen::Quaterniond orientation(const tinyxml2::XMLElement* e) const {
    const double unit = degrees_ ? std::numbers::pi / 180.0 : 1.0;
    if (const auto q = numbers(e, "quat", 4)) return Eigen::Quaterniond((*q)[0], (*q)[1], (*q)[2], (*q)[3]).normalized();
    if (const auto a = numbers(e, "axisangle", 4))
      return Eigen::Quaterniond(Eigen::AngleAxisd((*a)[3] * unit, Eigen::Vector3d((*a)[0], (*a)[1], (*a)[2]).normalized()));
    if (const auto angles = numbers(e, "euler", 3)) {
      Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
      if (euler_sequence_.size() != 3) throw InputError(where(e), "the compiler's eulerseq must have three letters");
      for (std::size_t i = 0; i < 3; ++i) {
        const char axis = euler_sequence_[i];
        const int k = std::tolower(static_cast<unsigned char>(axis)) - 'x';
        if (k < 0 || k > 2) throw InputError(where(e), "the compiler's eulerseq holds only x, y, z, X, Y, Z");
        const Eigen::Quaterniond r(Eigen::AngleAxisd((*angles)[i] * unit, Eigen::Vector3d::Unit(k)));
        // Lower case: about the moving axes (intrinsic); upper case: about the fixed ones.
        q = std::islower(static_cast<unsigned char>(axis)) ? q * r : r * q;
      }
      return q;
    }
    if (const auto xy = numbers(e, "xyaxes", 6)) {
      const Eigen::Vector3d x = Eigen::Vector3d((*xy)[0], (*xy)[1], (*xy)[2]).normalized();
      Eigen::Vector3d y((*xy)[3], (*xy)[4], (*xy)[5]);
      y = (y - y.dot(x) * x).normalized();
      Eigen::Matrix3d r;
      r << x, y, x.cross(y);
      return Eigen::Quaterniond(r);
    }
    if (const auto z = numbers(e, "zaxis", 3))
      return Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), Eigen::Vector3d((*z)[0], (*z)[1], (*z)[2]));
    return Eigen::Quaterniond::Identity();
  }

  static std::string text_of(const Eigen::Vector3d& v) { return fmt::format("{:.17g} {:.17g} {:.17g}", v.x(), v.y(), v.z()); }

  // <frame> (MuJoCo 3): a pose applied to the elements in it, which MuJoCo 2.2.2 does not know.
  // Each frame's pose is composed into its children's (pos, orientation, joint axes, fromto),
  // which then take its place, in order; a frame's childclass becomes their class (childclass
  // of a body). A child that takes its position from a default class is placed at the frame.
  void flatten_frames(tinyxml2::XMLElement* root) {
    std::vector<tinyxml2::XMLElement*> stack{root};
    while (!stack.empty()) {
      tinyxml2::XMLElement* e = stack.back();
      stack.pop_back();
      for (tinyxml2::XMLElement* child = e->FirstChildElement(); child;) {
        tinyxml2::XMLElement* next = child->NextSiblingElement();
        if (std::string_view(child->Name()) == "frame" && std::string_view(e->Name()) != "default") {
          tinyxml2::XMLElement* first = lift_frame(e, child);
          ++frames_;
          next = first ? first : next;  // the lifted children are visited (a nested frame in turn)
        } else {
          stack.push_back(child);
        }
        child = next;
      }
    }
    if (frames_ > 0)
      notices.push_back(fmt::format("{}: note: {} <frame>(s) (MuJoCo 3) read by composing each frame's pose into the elements "
                                    "it holds (MuJoCo 2.2.2 knows no frames)", path_, frames_));
  }

  // Moves the children of `frame` into `parent` in its place, poses composed; returns the first.
  tinyxml2::XMLElement* lift_frame(tinyxml2::XMLElement* parent, tinyxml2::XMLElement* frame) {
    const Eigen::Quaterniond q = orientation(frame);
    const auto frame_pos = numbers(frame, "pos", 3);
    const Eigen::Vector3d p = frame_pos ? Eigen::Vector3d((*frame_pos)[0], (*frame_pos)[1], (*frame_pos)[2]) : Eigen::Vector3d::Zero();
    const auto vector = [&](const tinyxml2::XMLElement* e, const char* name, const Eigen::Vector3d& otherwise) {
      const auto v = numbers(e, name, 3);
      return v ? Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]) : otherwise;
    };
    const char* childclass = frame->Attribute("childclass");
    tinyxml2::XMLNode* after = frame;
    tinyxml2::XMLElement* first = nullptr;
    for (tinyxml2::XMLElement* child = frame->FirstChildElement(); child;) {
      tinyxml2::XMLElement* next = child->NextSiblingElement();
      const std::string_view tag = child->Name();
      if (const auto ft = numbers(child, "fromto", 6)) {  // a geom or site between two points
        child->SetAttribute("fromto", (text_of(p + q * Eigen::Vector3d((*ft)[0], (*ft)[1], (*ft)[2])) + " " +
                                       text_of(p + q * Eigen::Vector3d((*ft)[3], (*ft)[4], (*ft)[5]))).c_str());
      } else if (tag == "joint") {  // a point and an axis (MuJoCo's default axis: z)
        child->SetAttribute("pos", text_of(p + q * vector(child, "pos", Eigen::Vector3d::Zero())).c_str());
        child->SetAttribute("axis", text_of(q * vector(child, "axis", Eigen::Vector3d::UnitZ())).c_str());
      } else if (tag == "light") {  // a point and a direction
        child->SetAttribute("pos", text_of(p + q * vector(child, "pos", Eigen::Vector3d::Zero())).c_str());
        child->SetAttribute("dir", text_of(q * vector(child, "dir", -Eigen::Vector3d::UnitZ())).c_str());
      } else if (tag != "freejoint") {  // a pose: body, geom, site, camera, frame
        child->SetAttribute("pos", text_of(p + q * vector(child, "pos", Eigen::Vector3d::Zero())).c_str());
        const Eigen::Quaterniond turned = q * orientation(child);
        for (const char* a : {"axisangle", "euler", "xyaxes", "zaxis"}) child->DeleteAttribute(a);
        child->SetAttribute("quat", fmt::format("{:.17g} {:.17g} {:.17g} {:.17g}", turned.w(), turned.x(), turned.y(), turned.z()).c_str());
      }
      if (childclass) {
        const char* attribute = tag == "body" ? "childclass" : "class";
        if (!child->Attribute(attribute)) child->SetAttribute(attribute, childclass);
      }
      parent->InsertAfterChild(after, child);
      after = child;
      if (!first) first = child;
      child = next;
    }
    parent->DeleteChild(frame);
    return first;
  }

  // Equalities between two sites (MuJoCo 2.3.3 and later: connect and weld with site1, site2)
  // -> the body-based ones MuJoCo 2.2.2 reads. A connect: body1 the body of site1, its anchor
  // the site's position in that body, body2 the body of site2 (the world when the site is in
  // <worldbody>). A weld: its bodies, anchor site2's position in body2 (where a weld with
  // torquescale 0 holds a point). The sites coincide in the assembled mechanism, which is where
  // kinestat reads it. A site's unnamed body is named as kinestat names it ("body<N>").
  void connect_sites(tinyxml2::XMLElement* root) {
    int welds = 0;
    for (tinyxml2::XMLElement* equality = root->FirstChildElement("equality"); equality;
         equality = equality->NextSiblingElement("equality"))
      for (tinyxml2::XMLElement* e = equality->FirstChildElement(); e; e = e->NextSiblingElement()) {
        const std::string_view tag = e->Name();
        if (tag != "connect" && tag != "weld") continue;
        const char* site1 = e->Attribute("site1");
        const char* site2 = e->Attribute("site2");
        if (!site1 && !site2) continue;
        if (!site1 || !site2) throw InputError(where(e), fmt::format("a site-based <{}> names both site1 and site2", tag));
        std::string body1 = body_of(site1, e, root), body2 = body_of(site2, e, root);
        const tinyxml2::XMLElement* anchor_site = sites_.at(tag == "weld" ? site2 : site1);
        if (tag == "connect" && body1 == "world") {  // the anchor goes on a body
          std::swap(body1, body2);
          anchor_site = sites_.at(site2);
        }
        if (body1 == "world" && body2 == "world")
          throw InputError(where(e), fmt::format("both sites of this <{}> are in <worldbody>: it joins nothing", tag));
        e->DeleteAttribute("site1");
        e->DeleteAttribute("site2");
        e->SetAttribute("body1", body1.c_str());
        if (body2 != "world") e->SetAttribute("body2", body2.c_str());
        e->SetAttribute("anchor", anchor_site->Attribute("pos") ? anchor_site->Attribute("pos") : "0 0 0");
        if (tag == "weld") {
          e->DeleteAttribute("relpose");  // MuJoCo ignores it for sites: the sites' frames coincide
          ++welds;
        } else {
          ++site_connects_;
        }
      }
    if (site_connects_ + welds > 0)
      notices.push_back(fmt::format("{}: note: {} site-based <connect>(s) and {} <weld>(s) read as equalities of the sites' "
                                    "bodies (MuJoCo 2.2.2 knows only body-based ones)", path_, site_connects_, welds));
  }

  // The name of the body that holds site `site` ("world" for <worldbody>); an unnamed body is
  // given the name kinestat reports it by, body<N> with N its number in MuJoCo's order.
  std::string body_of(const char* site, const tinyxml2::XMLElement* at, tinyxml2::XMLElement* root) {
    const auto found = sites_.find(site);
    if (found == sites_.end())
      throw InputError(where(at), fmt::format("no <site name=\"{}\"> for this <{}>", printable_text(std::string_view(site).substr(0, 60)),
                                              at->Name()));
    tinyxml2::XMLElement* parent = found->second->Parent() ? found->second->Parent()->ToElement() : nullptr;
    if (parent && std::string_view(parent->Name()) == "worldbody") return "world";
    if (!parent || std::string_view(parent->Name()) != "body")
      throw InputError(where(found->second), "a site that an equality names must be in a <body> (or in <worldbody>)");
    if (found->second->Attribute("fromto"))
      throw InputError(where(found->second), "a site that an equality names is placed by pos, not fromto");
    if (!parent->Attribute("name")) {
      // MuJoCo numbers bodies depth first in the order written, the world 0.
      int number = 0, id = 0;
      std::vector<const tinyxml2::XMLElement*> stack;
      for (const tinyxml2::XMLElement* w = root->LastChildElement("worldbody"); w; w = w->PreviousSiblingElement("worldbody"))
        stack.push_back(w);
      while (!stack.empty() && id == 0) {
        const tinyxml2::XMLElement* e = stack.back();
        stack.pop_back();
        if (std::string_view(e->Name()) == "body") {
          ++number;
          if (e == parent) id = number;
        }
        for (const tinyxml2::XMLElement* c = e->LastChildElement("body"); c; c = c->PreviousSiblingElement("body")) stack.push_back(c);
      }
      const std::string name = "body" + std::to_string(id);
      if (named_anywhere(root, name))
        throw InputError(where(parent), fmt::format("this body holds a site that an equality names: give it a name ('{}' is taken)", name));
      parent->SetAttribute("name", name.c_str());
    }
    return parent->Attribute("name");
  }

  static bool named_anywhere(const tinyxml2::XMLElement* root, const std::string& name) {
    std::vector<const tinyxml2::XMLElement*> stack{root};
    while (!stack.empty()) {
      const tinyxml2::XMLElement* e = stack.back();
      stack.pop_back();
      if (const char* n = e->Attribute("name"); n && name == n) return true;
      for (const tinyxml2::XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) stack.push_back(c);
    }
    return false;
  }

  void read_welds(const tinyxml2::XMLElement* root) {
    for (const tinyxml2::XMLElement* equality = root->FirstChildElement("equality"); equality;
         equality = equality->NextSiblingElement("equality"))
      for (const tinyxml2::XMLElement* e = equality->FirstChildElement(); e; e = e->NextSiblingElement()) {
        const char* scale = e->Attribute("torquescale");
        weld_as_connect.push_back(std::string_view(e->Name()) == "weld" && scale && std::strtod(scale, nullptr) == 0.0);
      }
  }

  // Prints the document, reads the print back and walks both element trees side by side: each
  // printed line gets the place its element was written, and each name its first element.
  void print() {
    tinyxml2::XMLPrinter printer;
    document_.Print(&printer);
    printed_.assign(printer.CStr(), static_cast<std::size_t>(std::max(printer.CStrSize() - 1, 0)));
    tinyxml2::XMLDocument again;
    again.Parse(printed_.data(), printed_.size());
    printed_lines_.assign(static_cast<std::size_t>(std::count(printed_.begin(), printed_.end(), '\n')) + 2, Origin{});
    std::vector<std::pair<const tinyxml2::XMLElement*, const tinyxml2::XMLElement*>> stack{{document_.RootElement(), again.RootElement()}};
    while (!stack.empty()) {
      const auto [original, copy] = stack.back();
      stack.pop_back();
      if (!original || !copy) continue;
      const Origin o = origin(original);
      Origin& line = printed_lines_[std::min<std::size_t>(static_cast<std::size_t>(copy->GetLineNum()), printed_lines_.size() - 1)];
      if (line.line == 0) line = o;
      if (const char* name = original->Attribute("name")) {
        Origin named = o;
        named.column = o.line > 0 ? column_of(o, original->Name()) : 0;
        named_.emplace(name, named);
      }
      for (auto [a, b] = std::pair{original->LastChildElement(), copy->LastChildElement()}; a && b;
           a = a->PreviousSiblingElement(), b = b->PreviousSiblingElement())
        stack.push_back({a, b});
    }
    for (std::size_t k = 1; k < printed_lines_.size(); ++k)
      if (printed_lines_[k].line == 0) printed_lines_[k] = printed_lines_[k - 1];
  }

  std::string path_;
  ImportOptions options_;
  bool folder_known_;
  std::string folder_;
  std::set<std::string> included_;  ///< canonical paths: MuJoCo includes a file once
  std::size_t total_bytes_ = 0;
  tinyxml2::XMLDocument document_;
  std::vector<std::unique_ptr<tinyxml2::XMLDocument>> parts_;
  std::unordered_map<const tinyxml2::XMLElement*, Origin> origins_;  ///< elements from included files
  std::string printed_;
  std::vector<Origin> printed_lines_;
  std::unordered_map<std::string, Origin> named_;
  std::unordered_map<std::string, std::unique_ptr<FileText>> texts_;  ///< by the file names in Origin
  std::unordered_map<std::string, tinyxml2::XMLElement*> sites_;  ///< by name, for site-based equalities
  int site_connects_ = 0;
  int frames_ = 0;
  bool degrees_ = true;              ///< the compiler's angle unit (MuJoCo's default: degree)
  std::string euler_sequence_ = "xyz";  ///< the compiler's eulerseq (MuJoCo's default)
};

class MjcfReader {
 public:
  MjcfReader(std::string path, const MjcfDocument& document) : path_(std::move(path)), document_(document) {}

  ImportedNetwork read(mjModel* raw, const char* error) {
    if (!raw) refuse_failed_load(error);
    const std::unique_ptr<mjModel, ModelDeleter> model(raw);
    const mjModel* m = model.get();
    if (static_cast<double>(m->nstack) * sizeof(mjtNum) + static_cast<double>(m->nbuffer) > kMaxDataBytes)
      throw InputError({path_, 0, 0}, "the model asks MuJoCo for more than 1 GiB of data (<size memory=...>)");
    const std::unique_ptr<mjData, DataDeleter> data(mj_makeData(m));
    mj_kinematics(m, data.get());  // world poses at the reference configuration qpos0
    const mjData* d = data.get();
    // MuJoCo has no length unit of its own; the model name comes first in `names`.
    NetworkBuilder builder(path_, m->nnames > 0 ? std::string(m->names) : std::string(), "");
    builder.set_ground(body_name(m, 0));
    couple_bodies(m, d, builder);
    const EqualityCouplings equalities = couple_equalities(m, d, builder);
    ImportedNetwork out{builder.finish(), document_.notices};
    if (!equalities.welds_as_connects.empty())
      out.notices.push_back(fmt::format("{}: note: weld(s) {} with torquescale 0 read as connect (a spherical coupling): MuJoCo "
                                        "then constrains the position only", path_, equalities.welds_as_connects));
    for (const std::string& w : warnings_) out.notices.push_back(fmt::format("{}: note: MuJoCo: {}", path_, w));
    if (!equalities.ignored.empty())
      out.notices.push_back(fmt::format("{}: note: equality constraint(s) {} ignored: only active connect and weld "
                                        "constraints are kinematic couplings", path_, equalities.ignored));
    return out;
  }

 private:
  // MuJoCo's messages end with "Element 'x', line N" (sometimes a column too), a line of the
  // printed document: it is mapped back to the file (an included one) and line written.
  [[noreturn]] void refuse_failed_load(const char* error) const {
    std::string message = error;
    const int line = mujoco_message_line(message);
    message = without_mujoco_places(message);
    for (char& c : message)
      if (c == '\n' || c == '\r') c = ' ';
    while (!message.empty() && message.back() == ' ') message.pop_back();
    throw InputError(document_.at_printed_line(line), "MuJoCo: " + printable_text(message));
  }

  // Each body's joints to its parent (a weld without joints: rigid), at the poses of `d`.
  void couple_bodies(const mjModel* m, const mjData* d, NetworkBuilder& builder) const {
    for (int b = 1; b < m->nbody; ++b) {
      const std::string body = body_name(m, b);
      std::string from = body_name(m, m->body_parentid[b]);
      const int count = m->body_jntnum[b];
      if (count == 0) {
        JointGeometry g;
        g.point = vec(d->xpos + 3 * b);
        builder.couple(body + " (welded)", screw::CouplingType::rigid, from, body, g, locate(body));
        continue;
      }
      for (int k = 0; k < count; ++k) {
        const int j = m->body_jntadr[b] + k;
        const std::string joint = name(m, mjOBJ_JOINT, j, "joint" + std::to_string(j));
        // Several joints in one body act in series: intermediate bodies carry the chain.
        const std::string to = k + 1 == count ? body : body + "/" + joint;
        JointGeometry g;
        g.point = vec(d->xanchor + 3 * j);
        screw::CouplingType type = screw::CouplingType::free;
        switch (m->jnt_type[j]) {
          case mjJNT_HINGE:
            type = screw::CouplingType::revolute;
            g.axis = vec(d->xaxis + 3 * j);
            break;
          case mjJNT_SLIDE:
            type = screw::CouplingType::prismatic;
            g.axis = vec(d->xaxis + 3 * j);
            break;
          case mjJNT_BALL: type = screw::CouplingType::spherical; break;
          default: type = screw::CouplingType::free; break;
        }
        builder.couple(joint, type, from, to, g, locate(joint));
        from = to;
      }
    }
  }

  // The equality constraints not read as couplings, and the welds read as connects (names,
  // comma-separated), for the notices.
  struct EqualityCouplings {
    std::string ignored, welds_as_connects;
  };

  // Each active connect (spherical) and weld (rigid; spherical with torquescale 0) equality.
  EqualityCouplings couple_equalities(const mjModel* m, const mjData* d, NetworkBuilder& builder) const {
    EqualityCouplings out;
    for (int e = 0; e < m->neq; ++e) {
      const std::string eq = name(m, mjOBJ_EQUALITY, e, "equality" + std::to_string(e));
      const int type = m->eq_type[e];
      if (type != mjEQ_CONNECT && type != mjEQ_WELD) {
        out.ignored += (out.ignored.empty() ? "" : ", ") + eq;
        continue;
      }
      if (!m->eq_active[e]) {
        out.ignored += (out.ignored.empty() ? "" : ", ") + eq + " (inactive)";
        continue;
      }
      const int b1 = m->eq_obj1id[e], b2 = m->eq_obj2id[e];
      JointGeometry g;
      const bool point_only = type == mjEQ_WELD && static_cast<std::size_t>(e) < document_.weld_as_connect.size() &&
                              document_.weld_as_connect[static_cast<std::size_t>(e)];
      if (point_only) {
        // A weld with torquescale 0 holds a point of body 2 (its anchor, in body 2's frame: the
        // first three numbers of a weld's eq_data) in place on body 1 and lets it turn.
        g.point = anchor_in_world(m, d, e, b2);
        out.welds_as_connects += (out.welds_as_connects.empty() ? "" : ", ") + eq;
      } else if (type == mjEQ_CONNECT) {
        g.point = anchor_in_world(m, d, e, b1);  // the anchor is given in body 1's frame
      } else {
        g.point = vec(d->xpos + 3 * b1);
      }
      builder.couple(eq, type == mjEQ_CONNECT || point_only ? screw::CouplingType::spherical : screw::CouplingType::rigid,
                     body_name(m, b1), body_name(m, b2), g, locate(eq));
    }
    return out;
  }

  // The anchor of equality `e` (the first three numbers of its eq_data, in body `b`'s frame) in
  // the world, at the poses of `d`.
  static Eigen::Vector3d anchor_in_world(const mjModel* m, const mjData* d, int e, int b) {
    const mjtNum* local = m->eq_data + mjNEQDATA * e;
    const mjtNum* x = d->xpos + 3 * b;
    const mjtNum* r = d->xmat + 9 * b;
    Eigen::Vector3d point;
    for (int i = 0; i < 3; ++i) point(i) = x[i] + r[3 * i] * local[0] + r[3 * i + 1] * local[1] + r[3 * i + 2] * local[2];
    return point;
  }

 private:
  static Eigen::Vector3d vec(const mjtNum* v) { return {v[0], v[1], v[2]}; }

  static std::string name(const mjModel* m, int type, int id, const std::string& fallback) {
    const char* n = mj_id2name(m, type, id);
    return n && *n ? n : fallback;
  }

  static std::string body_name(const mjModel* m, int b) { return name(m, mjOBJ_BODY, b, b == 0 ? "world" : "body" + std::to_string(b)); }

  // MuJoCo keeps no file positions: the element is found by its name, where it was written.
  SourceLocation locate(const std::string& object) const { return document_.where_named(object); }

  std::string path_;
  const MjcfDocument& document_;

 public:
  std::vector<std::string> warnings_;
};

// Loads through MuJoCo with its warnings collected into `reader`. MuJoCo's warning hook is one
// process-wide pointer (there is no per-call one in MuJoCo 2.2), so it is pointed at the
// collector only while mj_loadXML runs, one load at a time in the process, and the hook found
// (the caller's own, or null for MuJoCo's default) is put back after: the library leaves
// MuJoCo's global state as it found it. A warning another thread's MuJoCo raises during the load
// is collected too (the hook cannot tell threads apart). mju_user_error is left alone: the
// checks before the load (refuse_empty, the size limits) keep MuJoCo's fatal errors away.
mjModel* load(const char* file, const mjVFS* vfs, char (&error)[1024], MjcfReader& reader) {
  const std::lock_guard<std::mutex> lock(load_mutex);
  struct Hook {  // installed for this scope, the previous one restored however it is left
    void (*previous)(const char*) = mju_user_warning;
    explicit Hook(std::vector<std::string>* into) {
      warnings = into;
      mju_user_warning = collect_warning;
    }
    Hook(const Hook&) = delete;
    Hook& operator=(const Hook&) = delete;
    ~Hook() {
      mju_user_warning = previous;
      warnings = nullptr;
    }
  } hook(&reader.warnings_);
  return mj_loadXML(file, vfs, error, sizeof error);
}

// MuJoCo ends the process (mju_error, not an error message) on an empty file, and libmujoco
// 2.2.2 crashes on some malformed URDF, which it also reads: only an MJCF root reaches it (fuzzer).
void refuse_empty(const std::string& path, const std::string& text) {
  if (text.empty()) throw InputError({path, 0, 0}, "the file is empty: expected an MJCF model (<mujoco>)");
  const XmlRootElement root = xml_root_element(text);
  if (root.name != "mujoco") {
    const auto [line, column] = LineIndex(text).position(root.offset);
    throw InputError({path, line, column}, "expected an MJCF model: a <mujoco> root element");
  }
}

}  // namespace

bool mjcf_reader_built_in() { return true; }

namespace {

// The document built (includes, checks, assets stripped) and compiled by MuJoCo from memory: it
// reads no file of its own.
ImportedNetwork compile(const std::string& path, const std::string& text, const ImportOptions& options, bool folder_known) {
  refuse_empty(path, text);
  MjcfDocument document(path, options, folder_known);
  document.build(text);
  const std::string& printed = document.text();
  const std::unique_ptr<mjVFS, VfsDeleter> vfs(new mjVFS);
  mj_defaultVFS(vfs.get());
  if (mj_makeEmptyFileVFS(vfs.get(), "model.xml", static_cast<int>(printed.size())) != 0)
    throw InputError({path, 0, 0}, "MuJoCo: cannot hold the model in memory");
  const int index = mj_findFileVFS(vfs.get(), "model.xml");
  std::copy(printed.begin(), printed.end(), static_cast<char*>(vfs->filedata[index]));
  MjcfReader reader(path, document);
  char error[1024] = "";
  mjModel* m = load("model.xml", vfs.get(), error, reader);
  return reader.read(m, error);
}

}  // namespace

ImportedNetwork read_mjcf(const std::string& path, const ImportOptions& options) {
  return compile(path, read_text_file(path, options.max_input_bytes), options, true);
}

ImportedNetwork parse_mjcf(const std::string& path, const std::string& text) { return compile(path, text, {}, false); }

#else

bool mjcf_reader_built_in() { return false; }

ImportedNetwork read_mjcf(const std::string& path, const ImportOptions&) {
  throw InputError({path, 0, 0}, "MJCF is not built in: rebuild kinestat with libmujoco-dev and libtinyxml2-dev installed "
                                 "(docs/formats.md)");
}

ImportedNetwork parse_mjcf(const std::string& path, const std::string&) { return read_mjcf(path, {}); }

#endif

}  // namespace kinestat::io
