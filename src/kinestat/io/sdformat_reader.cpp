#include "kinestat/io/sdformat_reader.hpp"

#include <fmt/format.h>

#if KINESTAT_HAVE_SDFORMAT
#include <sdf/Error.hh>
#include <sdf/Joint.hh>
#include <sdf/JointAxis.hh>
#include <sdf/Link.hh>
#include <sdf/Model.hh>
#include <sdf/ParserConfig.hh>
#include <sdf/Root.hh>
#include <sdf/SDFImpl.hh>
#include <sdf/World.hh>
#include <sdf/parser.hh>

#include <Eigen/Geometry>

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <string_view>
#include <vector>

#include "kinestat/io/printable_text.hpp"
#include "kinestat/io/text_file.hpp"
#if KINESTAT_HAVE_TINYXML2
#include <tinyxml2.h>
#endif
#endif

namespace kinestat::io {

#if KINESTAT_HAVE_SDFORMAT

namespace {

/// libsdformat prints every problem to standard error (and urdfdom, which it tries on files
/// that are not SDFormat, does too), besides returning it. kinestat reports the returned
/// error as its one located line, so standard error is muted while the library reads.
class MutedStandardError {
 public:
  MutedStandardError() {
    std::cerr.flush();
    std::fflush(stderr);
    saved_ = ::dup(2);
    const int null = ::open("/dev/null", O_WRONLY);
    if (saved_ >= 0 && null >= 0) ::dup2(null, 2);
    if (null >= 0) ::close(null);
  }
  ~MutedStandardError() {
    std::cerr.flush();
    std::fflush(stderr);
    if (saved_ >= 0) {
      ::dup2(saved_, 2);
      ::close(saved_);
    }
  }
  MutedStandardError(const MutedStandardError&) = delete;
  MutedStandardError& operator=(const MutedStandardError&) = delete;

 private:
  int saved_ = -1;
};

Eigen::Vector3d vector(const ignition::math::Vector3d& v) { return {v.X(), v.Y(), v.Z()}; }

/// x_outer = rotation * x_inner + origin.
struct SdfFrame {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
};

SdfFrame frame(const ignition::math::Pose3d& pose) {
  const auto& q = pose.Rot();
  return {Eigen::Quaterniond(q.W(), q.X(), q.Y(), q.Z()).normalized().toRotationMatrix(), vector(pose.Pos())};
}

class SdformatReader {
 public:
  explicit SdformatReader(std::string path) : path_(std::move(path)) {}

  ImportedNetwork read(const sdf::Root& root, const sdf::Errors& errors) {
    if (!errors.empty()) fail(errors.front());
    std::vector<std::pair<const sdf::Model*, SdfFrame>> models;
    std::string name;
    if (const sdf::Model* single = root.Model()) {
      models.push_back({single, SdfFrame{}});
      name = single->Name();
    } else {
      for (std::uint64_t w = 0; w < root.WorldCount(); ++w) {
        const sdf::World* world = root.WorldByIndex(w);
        if (name.empty()) name = world->Name();
        for (std::uint64_t m = 0; m < world->ModelCount(); ++m) {
          const sdf::Model* model = world->ModelByIndex(m);
          ignition::math::Pose3d pose;
          const sdf::Errors e = model->SemanticPose().Resolve(pose, "world");
          if (!e.empty()) fail(e.front());
          models.push_back({model, frame(pose)});
          world_ = true;  // several models in a world: each link's name is scoped by its model
        }
      }
    }
    if (models.empty()) throw InputError({path_, 1, 1}, "the file holds no <model>");
    NetworkBuilder builder(path_, name, "m");  // SDFormat lengths are metres
    for (const auto& [model, placed] : models) read_model(builder, *model, placed, world_ ? model->Name() + "::" : "");
    if (grounded_.empty()) grounded_ = ground_candidate_;
    builder.set_ground(grounded_);
    ImportedNetwork out{builder.finish(), {}};
    return out;
  }

 private:
  [[noreturn]] void fail(const sdf::Error& error) const {
    const std::string file = error.FilePath().value_or("");
    throw InputError({file.empty() ? path_ : file, error.LineNumber().value_or(0), error.LineNumber() ? 1 : 0}, error.Message());
  }

  SourceLocation where(const sdf::ElementPtr& element) const {
    if (!element) return {path_, 0, 0};
    const auto line = element->LineNumber();
    return {element->FilePath().empty() ? path_ : element->FilePath(), line.value_or(0), line ? 1 : 0};
  }

  void read_model(NetworkBuilder& builder, const sdf::Model& model, const SdfFrame& placed, const std::string& scope) {
    for (std::uint64_t l = 0; l < model.LinkCount(); ++l) builder.body(scope + model.LinkByIndex(l)->Name());
    if (ground_candidate_.empty() && !model.CanonicalLinkName().empty()) ground_candidate_ = scope + model.CanonicalLinkName();
    // SDFormat's default canonical link is the first one; libsdformat leaves the name empty for
    // some documents it converted from old versions.
    if (ground_candidate_.empty() && model.LinkCount() > 0) ground_candidate_ = scope + model.LinkByIndex(0)->Name();
    for (std::uint64_t j = 0; j < model.JointCount(); ++j) read_joint(builder, *model.JointByIndex(j), placed, scope);
    for (std::uint64_t m = 0; m < model.ModelCount(); ++m) {
      const sdf::Model* nested = model.ModelByIndex(m);
      ignition::math::Pose3d pose;
      const sdf::Errors e = nested->SemanticPose().Resolve(pose, "__model__");
      if (!e.empty()) fail(e.front());
      const SdfFrame inner = frame(pose);
      read_model(builder, *nested, {placed.rotation * inner.rotation, placed.rotation * inner.origin + placed.origin},
                 scope + nested->Name() + "::");
    }
  }

  std::string link(const sdf::Joint& joint, bool parent, const std::string& scope) {
    std::string name;
    const sdf::Errors e = parent ? joint.ResolveParentLink(name) : joint.ResolveChildLink(name);
    if (!e.empty()) fail(e.front());
    if (name == "world") {
      grounded_ = "world";
      return name;
    }
    return scope + name;
  }

  Eigen::Vector3d axis(const sdf::Joint& joint, unsigned index, const SdfFrame& placed) const {
    const sdf::JointAxis* a = joint.Axis(index);
    if (!a) throw InputError(where(joint.Element()), fmt::format("joint '{}' needs an <axis{}>", joint.Name(), index ? "2" : ""));
    ignition::math::Vector3d xyz;
    const sdf::Errors e = a->ResolveXyz(xyz, "__model__");
    if (!e.empty()) fail(e.front());
    return placed.rotation * vector(xyz);
  }

  void read_joint(NetworkBuilder& builder, const sdf::Joint& joint, const SdfFrame& placed, const std::string& scope) {
    ignition::math::Pose3d pose;
    const sdf::Errors e = joint.SemanticPose().Resolve(pose, "__model__");
    if (!e.empty()) fail(e.front());
    const SdfFrame f = frame(pose);
    JointGeometry g;
    g.point = placed.rotation * f.origin + placed.origin;
    screw::CouplingType type = screw::CouplingType::rigid;
    switch (joint.Type()) {
      case sdf::JointType::REVOLUTE:
      case sdf::JointType::CONTINUOUS:
        type = screw::CouplingType::revolute;
        g.axis = axis(joint, 0, placed);
        break;
      case sdf::JointType::PRISMATIC:
        type = screw::CouplingType::prismatic;
        g.axis = axis(joint, 0, placed);
        break;
      case sdf::JointType::SCREW:
        // SDFormat's thread_pitch is radians per length with a positive value for a left-handed
        // thread (SDFormat 1.11 spec; libsdformat's Joint.cc: screw_thread_pitch, length per
        // revolution and positive right-handed, is -2 pi / thread_pitch). kinestat's pitch is
        // length per radian, positive right-handed: -1 / thread_pitch.
        type = screw::CouplingType::helical;
        g.axis = axis(joint, 0, placed);
        if (joint.ThreadPitch() == 0.0)
          throw InputError(where(joint.Element()), fmt::format("screw joint '{}' has thread_pitch 0", joint.Name()));
        g.pitch = -1.0 / joint.ThreadPitch();
        break;
      case sdf::JointType::UNIVERSAL:
      case sdf::JointType::REVOLUTE2:
        type = screw::CouplingType::universal;
        g.axis = axis(joint, 0, placed);
        g.axis2 = axis(joint, 1, placed);
        break;
      case sdf::JointType::BALL: type = screw::CouplingType::spherical; break;
      case sdf::JointType::FIXED: type = screw::CouplingType::rigid; break;
      case sdf::JointType::GEARBOX:
      case sdf::JointType::INVALID:
        throw InputError(where(joint.Element()), fmt::format("joint '{}': gearbox joints couple two rotations by a ratio, "
                                                             "which a coupling network cannot express", joint.Name()));
    }
    builder.couple(scope + joint.Name(), type, link(joint, true, scope), link(joint, false, scope), g, where(joint.Element()));
  }

  std::string path_;
  bool world_ = false;
  std::string grounded_, ground_candidate_;
};

}  // namespace

bool sdformat_reader_built_in() { return true; }

#if KINESTAT_HAVE_TINYXML2
namespace {

// What libsdformat's version parser takes without throwing: whole numbers joined by dots, each
// short enough for std::stoi.
bool plain_version(std::string_view version) {
  std::size_t digits = 0, parts = 0;
  for (const char c : version) {
    if (c == '.') {
      if (digits == 0) return false;
      digits = 0;
    } else if (c >= '0' && c <= '9') {
      if (digits++ == 0) ++parts;
      if (digits > 6) return false;
    } else {
      return false;
    }
  }
  return digits > 0 && parts <= 3;
}

// libsdformat 12 clones the whole description of an element for every <link> and <joint> it
// reads (with all their possible children): about 0.7 MB and 5 ms each, so 10^4 joints take
// 82 s and 14 GB. Models beyond this many links and joints are refused before it starts.
constexpr std::size_t kMaxSdformatLinksAndJoints = 2000;

// The <link> and <joint> elements of the document, counted without recursion.
std::size_t links_and_joints(const tinyxml2::XMLElement* root) {
  std::size_t count = 0;
  std::vector<const tinyxml2::XMLElement*> stack{root};
  while (!stack.empty()) {
    const tinyxml2::XMLElement* e = stack.back();
    stack.pop_back();
    const std::string_view name = e->Name();
    if (name == "link" || name == "joint") ++count;
    for (const tinyxml2::XMLElement* child = e->FirstChildElement(); child; child = child->NextSiblingElement()) stack.push_back(child);
  }
  return count;
}

}  // namespace
#endif

// libsdformat reports malformed XML only as "Unable to read file" (the line goes to its
// console), and tries a URDF conversion on other roots: check both first, with positions.
// Its version parser (ignition::math::SemanticVersion) throws std::invalid_argument on a
// version such as "1.M" from a place the exception cannot leave (std::terminate, found by
// fuzz_sdformat_file): the version is checked here first.
void check_xml(const std::string& path, const std::string& text) {
#if KINESTAT_HAVE_TINYXML2
  tinyxml2::XMLDocument document;
  if (document.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS)
    throw InputError({path, document.ErrorLineNum(), 1}, fmt::format("malformed XML: {}", document.ErrorStr()));
  if (const tinyxml2::XMLElement* root = document.RootElement(); root != nullptr && std::string_view(root->Name()) == "sdf") {
    const char* version = root->Attribute("version");
    if (version != nullptr && !plain_version(version))
      throw InputError({path, root->GetLineNum(), 1},
                       fmt::format("<sdf version=\"{}\">: a version is whole numbers joined by dots, such as 1.9",
                                   printable_text(std::string_view(version).substr(0, 40))));
    if (const std::size_t count = links_and_joints(root); count > kMaxSdformatLinksAndJoints)
      throw InputError({path, root->GetLineNum(), 1},
                       fmt::format("the file has {} <link> and <joint> elements; kinestat reads at most {} from an SDFormat "
                                   "file, because libsdformat 12 needs about 0.7 MB and 5 ms for each (convert the model to "
                                   "URDF, which is read without this limit)",
                                   count, kMaxSdformatLinksAndJoints));
  }
#endif
  if (xml_root_name(text) != "sdf") throw InputError({path, 1, 1}, "an SDFormat file has an <sdf> root element");
}

namespace {

/// An empty document that knows the SDFormat description (root.sdf and all it includes).
/// libsdformat's Root::Load and LoadSdfString parse that description again for every document,
/// and a deep Clone costs as much, which is most of the time a small model takes (and of
/// fuzz_sdformat_file's). The description is parsed once; each document gets its own root
/// element that shares the child descriptions, which reading only clones and never changes.
sdf::SDFPtr described_document() {
  static const sdf::ElementPtr description = [] {
    const auto document = std::make_shared<sdf::SDF>();
    sdf::init(document);
    return document->Root();
  }();
  auto root = std::make_shared<sdf::Element>();
  root->SetName(description->GetName());
  root->SetRequired(description->GetRequired());
  root->SetDescription(description->GetDescription());
  root->SetCopyChildren(description->GetCopyChildren());
  root->SetReferenceSDF(description->ReferenceSDF());
  root->SetFilePath(description->FilePath());  // the rest of what Element::Clone copies
  root->SetXmlPath(description->XmlPath());
  root->SetOriginalVersion(description->OriginalVersion());
  root->SetExplicitlySetInFile(description->GetExplicitlySetInFile());
  if (const auto line = description->LineNumber()) root->SetLineNumber(*line);
  for (const sdf::ParamPtr& attribute : description->GetAttributes())
    root->AddAttribute(attribute->GetKey(), attribute->GetTypeName(), attribute->GetDefaultAsString(),
                       attribute->GetRequired(), attribute->GetDescription());
  for (std::size_t i = 0; i < description->GetElementDescriptionCount(); ++i)
    root->AddElementDescription(description->GetElementDescription(static_cast<unsigned>(i)));
  auto document = std::make_shared<sdf::SDF>();
  document->Root(root);
  return document;
}

/// Reads a document into a described copy with `read_into` (libsdformat's readFile or
/// readString), then builds the DOM: what Root::Load(path) and Root::LoadSdfString do, with
/// the same errors in the same order.
template <class ReadInto>
ImportedNetwork load(const std::string& path, ReadInto read_into, const sdf::Error& unreadable) {
  sdf::Root root;
  sdf::Errors errors;
  {
    const MutedStandardError muted;
    const sdf::ParserConfig& config = sdf::ParserConfig::GlobalConfig();
    const sdf::SDFPtr document = described_document();
    if (read_into(config, document, errors)) {
      const sdf::Errors built = root.Load(document, config);
      errors.insert(errors.end(), built.begin(), built.end());
    } else {
      errors.push_back(unreadable);
    }
  }
  return SdformatReader(path).read(root, errors);
}

}  // namespace

ImportedNetwork read_sdformat(const std::string& path) {
  check_xml(path, read_text_file(path));
  return load(
      path,
      [&](const sdf::ParserConfig& config, const sdf::SDFPtr& document, sdf::Errors& errors) {
        return sdf::readFile(path, config, document, errors);
      },
      sdf::Error(sdf::ErrorCode::FILE_READ, "Unable to read file:" + path));
}

ImportedNetwork parse_sdformat(const std::string& path, const std::string& text) {
  check_xml(path, text);
  return load(
      path,
      [&](const sdf::ParserConfig& config, const sdf::SDFPtr& document, sdf::Errors& errors) {
        return sdf::readString(text, config, document, errors);
      },
      sdf::Error(sdf::ErrorCode::STRING_READ, "Unable to read SDF string"));
}

#else

bool sdformat_reader_built_in() { return false; }

ImportedNetwork read_sdformat(const std::string& path) {
  throw InputError({path, 0, 0}, "SDFormat is not built in: rebuild kinestat with libsdformat-dev installed (docs/formats.md)");
}

ImportedNetwork parse_sdformat(const std::string& path, const std::string&) { return read_sdformat(path); }

#endif

}  // namespace kinestat::io
