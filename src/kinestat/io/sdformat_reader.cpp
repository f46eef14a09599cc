// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/io/sdformat_reader.hpp"

#include <fmt/format.h>

#if KINESTAT_HAVE_SDFORMAT && KINESTAT_HAVE_TINYXML2
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

#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "kinestat/io/printable_text.hpp"
#include "kinestat/io/text_file.hpp"
#endif

namespace kinestat::io {

#if KINESTAT_HAVE_SDFORMAT && KINESTAT_HAVE_TINYXML2

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

// What libsdformat's version parser takes without throwing: whole numbers joined by dots, each
// short enough for std::stoi. Its parser (ignition::math::SemanticVersion) throws
// std::invalid_argument on a version such as "1.M" from a place the exception cannot leave
// (std::terminate, found by fuzz_sdformat_file), and an included file with such a version gave
// "internal error: stoi": every file's version is checked here first.
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
// 82 s and 14 GB. Models beyond this many links and joints (includes expanded) are refused
// before it starts.
constexpr std::size_t kMaxSdformatLinksAndJoints = 2000;

std::string trimmed(const char* text) {
  std::string_view view = text ? text : "";
  while (!view.empty() && std::isspace(static_cast<unsigned char>(view.front()))) view.remove_prefix(1);
  while (!view.empty() && std::isspace(static_cast<unsigned char>(view.back()))) view.remove_suffix(1);
  return std::string(view);
}

// Elements whose content never changes which links and joints a model has or where they are:
// they are removed before libsdformat reads the model, so that an error in one (a material
// script without <uri>, a friction <mu> of -1, which make libsdformat drop the whole document)
// cannot stop the import (issue 37), and no mesh or texture is ever looked for. <inertial> too:
// libsdformat refuses a link whose inertia is not physical (Gazebo's simple_arm), which says
// nothing about its joints.
// True for text that holds three numbers, all zero (an <xyz> axis libsdformat refuses).
bool zero_vector(const char* text) {
  if (!text) return false;
  int count = 0;
  for (const char* p = text;; ++count) {
    char* end = nullptr;
    const double x = std::strtod(p, &end);
    if (end == p) break;
    if (x != 0.0) return false;
    p = end;
  }
  return count == 3;
}

// The name a joint named "world" has while libsdformat reads it (no SDFormat name can hold a space).
constexpr const char* kRenamedWorldJoint = "joint named world";

bool without_kinematic_meaning(std::string_view tag) {
  for (const char* name : {"visual", "collision", "inertial", "material", "sensor", "plugin", "audio_sink", "audio_source", "battery",
                           "light", "actor", "projector", "particle_emitter", "gui", "scene", "physics", "atmosphere", "wind",
                           "spherical_coordinates"})
    if (tag == name) return true;
  return false;
}

/// The files of one SDFormat model: the file given and every file it includes, each read
/// through the bounded reader and checked (XML, <sdf> version) before libsdformat sees it, and
/// given to libsdformat as a copy (in a private folder) without the elements that have no
/// kinematic meaning and with each <include><uri> resolved here, beside the file that holds it,
/// as an absolute path. The copies' lines are mapped back to the files' own.
class ModelFiles {
 public:
  /// `path`: the file given; `folder_known`: false for text without a file (no includes).
  ModelFiles(std::string path, const ImportOptions& options, bool folder_known)
      : path_(std::move(path)), options_(options), folder_known_(folder_known) {}
  ModelFiles(const ModelFiles&) = delete;
  /// What the user allows and asks (includes outside the folder, the base).
  const ImportOptions& options() const { return options_; }
  ModelFiles& operator=(const ModelFiles&) = delete;
  ~ModelFiles() {
    std::error_code ignored;
    if (!private_folder_.empty()) std::filesystem::remove_all(private_folder_, ignored);
  }

  /// Checks the file given (its `text`) and everything it includes; returns the path of the
  /// copy libsdformat is to read ("" for text without a file: then main_text()).
  std::string prepare(const std::string& text) {
    std::string canonical = path_;
    if (folder_known_) {
      std::error_code error;
      canonical = std::filesystem::weakly_canonical(path_, error).string();
      if (error) canonical = path_;
      folder_ = std::filesystem::path(canonical).parent_path().string();
    }
    std::vector<std::string> chain{canonical};
    const File& main = process(path_, canonical, text, chain);
    if (!stripped_.empty()) {
      std::string names;
      for (const auto& [name, count] : stripped_) names += fmt::format("{}{} <{}>", names.empty() ? "" : ", ", count, name);
      notices_.push_back(fmt::format("{}: note: ignored {} (no kinematic meaning): libsdformat never reads them, so an error in "
                                     "one (a material, a friction value, a mesh) cannot stop the import",
                                     path_, names));
    }
    return main.copy;
  }

  /// The copy of the file given, for text without a file.
  const std::string& main_text() const { return main_->copy_text; }

  /// What was ignored, for the report's notices.
  const std::vector<std::string>& notices() const { return notices_; }

  /// Where a place that libsdformat reports (its file, a line or 0) is for the user: the file
  /// as given or included, and its own line.
  SourceLocation original(const std::string& file, int line) const {
    const File* found = find(file);
    if (!found) return {file.empty() ? path_ : file, line, line > 0 ? 1 : 0};
    if (line > 0 && !found->line_of.empty()) line = found->line_of[std::min<std::size_t>(static_cast<std::size_t>(line), found->line_of.size() - 1)];
    return {found->shown, line, line > 0 ? 1 : 0};
  }

  /// For a libsdformat message without a line ("... joint with name[j] not found in model with
  /// name[m]"): where the first element it names by kind and name was written, if one was.
  std::optional<SourceLocation> named_in(const std::string& message) const {
    // "KIND with name[NAME]" (NAME of 1 to 200 characters), scanned by hand: std::regex cost this
    // file 20 s of compile time.
    static constexpr std::string_view kMarker = " with name[";
    for (std::size_t at = message.find(kMarker); at != std::string::npos; at = message.find(kMarker, at + 1)) {
      const std::string_view before = std::string_view(message).substr(0, at);
      std::string_view kind;
      for (std::string_view k : {"joint", "link", "frame", "model", "world"})
        if (before.ends_with(k)) kind = k;
      const std::size_t name_begin = at + kMarker.size();
      const std::size_t close = message.find(']', name_begin);
      if (kind.empty() || close == std::string::npos || close == name_begin || close - name_begin > 200) continue;
      const auto found = named_.find(std::string(kind) + ":" + message.substr(name_begin, close - name_begin));
      if (found != named_.end()) return found->second;
      at = close;
    }
    // "The norm of the xyz vector cannot be zero" names no element: the first zero <xyz>.
    if (message.find("xyz vector") != std::string::npos && zero_axis_) return zero_axis_;
    return std::nullopt;
  }

  /// `message` with the paths of the private copies replaced by the files they copy.
  std::string shown(std::string message) const {
    for (const auto& [canonical, file] : files_) {
      if (file.copy.empty()) continue;
      for (std::size_t at = message.find(file.copy); at != std::string::npos; at = message.find(file.copy, at + file.shown.size()))
        message.replace(at, file.copy.size(), file.shown);
    }
    return message;
  }

 private:
  struct File {
    std::string shown;  ///< the path as the user knows it (given, or canonical for included files)
    std::string copy;   ///< the path of the copy libsdformat reads ("" for text without a file)
    std::string copy_text;
    std::vector<int> line_of;                               ///< the copy's line -> the file's line
    std::uint64_t expanded_bytes = 0;                       ///< with every include expanded
    std::size_t links_and_joints = 0;                       ///< with every include expanded
    bool includes = false;
  };

  const File* find(const std::string& file) const {
    if (file.empty() || file == path_ || file == "<data-string>" || file == "data-string") return main_;
    for (const auto& [canonical, f] : files_)
      if (file == canonical || file == f.copy || file == f.shown) return &f;
    return nullptr;
  }

  [[noreturn]] static void refuse(const SourceLocation& where, const std::string& problem) { throw InputError(where, problem); }

  // Checked as soon as a file is counted (before any copy is written), so that a model far past
  // the limit is refused in the time it takes to parse it.
  void check_size(const File& file, bool with_includes) const {
    if (file.links_and_joints <= kMaxSdformatLinksAndJoints) return;
    refuse({path_, 1, 1}, fmt::format("the file has {} <link> and <joint> elements{}; kinestat reads at most {} from an "
                                      "SDFormat model, because libsdformat 12 needs about 0.7 MB and 5 ms for each (convert the "
                                      "model to URDF, which is read without this limit)",
                                      file.links_and_joints, with_includes ? " with its includes" : "", kMaxSdformatLinksAndJoints));
  }

  const File& process(const std::string& shown, const std::string& canonical, const std::string& text,
                      std::vector<std::string>& chain) {
    if (const auto done = files_.find(canonical); done != files_.end()) return done->second;
    File file;
    file.shown = shown;
    file.expanded_bytes = text.size();
    tinyxml2::XMLDocument document;
    if (document.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS)
      refuse({shown, document.ErrorLineNum(), 1}, fmt::format("malformed XML: {}", printable_text(document.ErrorStr())));
    tinyxml2::XMLElement* root = document.RootElement();
    if (!root || std::string_view(root->Name()) != "sdf")
      refuse({shown, root ? root->GetLineNum() : 1, 1}, "an SDFormat file has an <sdf> root element");
    const char* version = root->Attribute("version");
    if (version != nullptr && !plain_version(version))
      refuse({shown, root->GetLineNum(), 1}, fmt::format("<sdf version=\"{}\">: a version is whole numbers joined by dots, such as 1.9",
                                                         printable_text(std::string_view(version).substr(0, 40))));
    std::vector<tinyxml2::XMLElement*> includes, stripped;
    std::vector<tinyxml2::XMLElement*> stack{root};
    while (!stack.empty()) {
      tinyxml2::XMLElement* e = stack.back();
      stack.pop_back();
      const std::string_view name = e->Name();
      if (without_kinematic_meaning(name)) {
        stripped.push_back(e);
        ++stripped_[std::string(name)];
        continue;
      }
      if (name == "link" || name == "joint") ++file.links_and_joints;
      if (name == "xyz" && !zero_axis_ && zero_vector(e->GetText())) zero_axis_ = SourceLocation{shown, e->GetLineNum(), 1};
      // SDFormat reserves the name "world" for the world frame; libsdformat refuses a joint so
      // named (Gazebo's fire_hose_long_curled has one), though the name says nothing of the
      // joint: it reaches libsdformat renamed and is reported under its own name.
      if (const char* joint_name = e->Attribute("name"); name == "joint" && joint_name && std::string_view(joint_name) == "world") {
        e->SetAttribute("name", kRenamedWorldJoint);
        if (renamed_world_joints_++ == 0)
          notices_.push_back(fmt::format("{}:{}: note: a joint named 'world' (a name SDFormat reserves for the world frame, "
                                         "which libsdformat refuses) read under its own name", shown, e->GetLineNum()));
      }
      if (name == "include") includes.push_back(e);
      if (const char* element_name = e->Attribute("name"))
        named_.emplace(std::string(name) + ":" + element_name, SourceLocation{shown, e->GetLineNum(), 1});
      for (tinyxml2::XMLElement* child = e->FirstChildElement(); child; child = child->NextSiblingElement()) stack.push_back(child);
    }
    check_size(file, false);
    for (tinyxml2::XMLElement* e : stripped) e->Parent()->DeleteChild(e);
    const std::string folder = std::filesystem::path(canonical).parent_path().string();
    for (tinyxml2::XMLElement* include : includes) {
      tinyxml2::XMLElement* uri = include->FirstChildElement("uri");
      if (!uri) continue;  // libsdformat says what is missing
      const std::string written = trimmed(uri->GetText());
      const SourceLocation where{shown, uri->GetLineNum(), 1};
      if (!folder_known_)
        refuse(where, "an <include> is resolved beside the file that holds it: read the model from its file, not from text");
      if (static_cast<int>(chain.size()) > kMaxIncludeDepth)
        refuse(where, fmt::format("includes nested more than {} files deep (each file includes the next); kinestat stops there",
                                  kMaxIncludeDepth));
      const std::string target = resolve(written, folder, where);
      for (std::size_t k = 0; k < chain.size(); ++k)
        if (chain[k] == target)
          refuse(where, fmt::format("'{}' is {}, which is already being read: a file that includes itself{}", printable_text(written),
                                    printable_text(target), k + 1 < chain.size() ? " through the files it includes" : ""));
      chain.push_back(target);
      const File& child = process(target, target, read_text_file(target, options_.max_input_bytes), chain);
      chain.pop_back();
      file.expanded_bytes += child.expanded_bytes;
      file.links_and_joints += child.links_and_joints;
      check_size(file, true);
      if (file.expanded_bytes > options_.max_input_bytes)
        refuse(where, fmt::format("with its includes expanded the model is larger than the {} limit on model files "
                                  "(--max-input-size)",
                                  size_text(options_.max_input_bytes)));
      uri->SetText(child.copy.c_str());
      file.includes = true;
    }
    write_copy(file, document);
    const bool is_main = chain.size() == 1;
    const File& stored = files_.emplace(canonical, std::move(file)).first->second;
    if (is_main) main_ = &stored;
    return stored;
  }

  // The include as written -> the canonical path of the SDFormat file it names. Only the
  // including file's folder is searched (and, for model://name, the folder above it, where a
  // collection of models keeps its siblings): never the working directory, SDF_PATH or /usr/share.
  std::string resolve(const std::string& written, const std::string& folder, const SourceLocation& where) const {
    namespace fs = std::filesystem;
    std::vector<fs::path> candidates;
    const std::size_t scheme_end = written.find("://");
    if (scheme_end != std::string::npos) {
      const std::string scheme = written.substr(0, scheme_end);
      const fs::path rest = written.substr(scheme_end + 3);
      if (scheme == "file") {
        candidates.push_back(rest.is_absolute() ? rest : fs::path(folder) / rest);
      } else if (scheme == "model" || scheme == "package") {
        candidates.push_back(fs::path(folder) / rest);
        candidates.push_back(fs::path(folder).parent_path() / rest);
      } else {
        refuse(where, fmt::format("kinestat reads no '{}://' URI (it downloads nothing and searches no system folder): give "
                                  "the included file's path relative to the file that includes it",
                                  printable_text(std::string_view(scheme).substr(0, 20))));
      }
    } else {
      const fs::path written_path(written);
      candidates.push_back(written_path.is_absolute() ? written_path : fs::path(folder) / written_path);
    }
    std::error_code error;
    fs::path found;
    for (const fs::path& candidate : candidates)
      if (!written.empty() && fs::exists(candidate, error)) {
        found = candidate;
        break;
      }
    if (found.empty()) {
      std::string looked;
      for (const fs::path& candidate : candidates) looked += (looked.empty() ? "" : " and ") + candidate.lexically_normal().string();
      refuse(where, fmt::format("the included file '{}' is not found beside the file that includes it (looked for {}); kinestat "
                                "never looks in the working directory or system folders",
                                printable_text(written), printable_text(looked)));
    }
    if (fs::is_directory(found, error)) found = model_in_folder(found, where);
    return allowed_include(found.string(), folder_, options_, where, written);
  }

  // A model folder (Gazebo's layout): the SDFormat file named by its model.config (the newest
  // <sdf> version libsdformat reads), or model.sdf.
  std::filesystem::path model_in_folder(const std::filesystem::path& folder, const SourceLocation& where) const {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::path config = folder / "model.config";
    if (!fs::exists(config, error)) {
      if (fs::exists(folder / "model.sdf", error)) return folder / "model.sdf";
      refuse(where, fmt::format("the included folder {} has neither a model.config nor a model.sdf", printable_text(folder.string())));
    }
    const std::string text = read_text_file(config.string(), options_.max_input_bytes);
    tinyxml2::XMLDocument document;
    if (document.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS)
      refuse({config.string(), document.ErrorLineNum(), 1}, fmt::format("malformed XML: {}", printable_text(document.ErrorStr())));
    const tinyxml2::XMLElement* model = document.RootElement();
    std::string best, best_version;
    for (const tinyxml2::XMLElement* sdf = model ? model->FirstChildElement("sdf") : nullptr; sdf; sdf = sdf->NextSiblingElement("sdf")) {
      const char* version = sdf->Attribute("version");
      const std::string v = version && plain_version(version) ? version : "";
      const auto number = [](const std::string& x) { return x.empty() ? 0.0 : std::strtod(x.c_str(), nullptr); };
      if (best.empty() || (number(v) > number(best_version) && number(v) <= 1.9)) {
        best = trimmed(sdf->GetText());
        best_version = v;
      }
    }
    if (best.empty()) refuse({config.string(), model ? model->GetLineNum() : 1, 1}, "a model.config names its SDFormat file in <sdf>");
    return folder / best;
  }

  // The file as libsdformat is to read it (its includes now absolute paths), in the private
  // folder, with the map from the copy's lines to the file's: the copy is printed by tinyxml2,
  // read back, and both element trees walked side by side.
  void write_copy(File& file, const tinyxml2::XMLDocument& document) {
    tinyxml2::XMLPrinter printer;
    document.Print(&printer);
    file.copy_text.assign(printer.CStr(), static_cast<std::size_t>(std::max(printer.CStrSize() - 1, 0)));
    const std::string& text = file.copy_text;
    if (folder_known_ && private_folder_.empty()) {
      std::string pattern = (std::filesystem::temp_directory_path() / "kinestat-sdf-XXXXXX").string();
      if (::mkdtemp(pattern.data()) == nullptr) refuse({file.shown, 0, 0}, "cannot make a private folder for the copies of the model's files");
      private_folder_ = pattern;
    }
    if (folder_known_) {
      file.copy = (std::filesystem::path(private_folder_) / fmt::format("{}.sdf", copies_++)).string();
      std::ofstream out(file.copy, std::ios::binary);
      out << text;
      if (!out.flush()) refuse({file.shown, 0, 0}, "cannot write the copy of the model that libsdformat reads");
    }
    tinyxml2::XMLDocument again;
    again.Parse(text.data(), text.size());
    std::vector<std::pair<const tinyxml2::XMLElement*, const tinyxml2::XMLElement*>> stack{{document.RootElement(), again.RootElement()}};
    file.line_of.assign(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 2, 0);
    while (!stack.empty()) {
      const auto [original, copy] = stack.back();
      stack.pop_back();
      if (!original || !copy) continue;
      auto& line = file.line_of[std::min<std::size_t>(static_cast<std::size_t>(copy->GetLineNum()), file.line_of.size() - 1)];
      if (line == 0) line = original->GetLineNum();
      for (auto [a, b] = std::pair{original->FirstChildElement(), copy->FirstChildElement()}; a && b;
           a = a->NextSiblingElement(), b = b->NextSiblingElement())
        stack.push_back({a, b});
    }
    for (std::size_t k = 1; k < file.line_of.size(); ++k)
      if (file.line_of[k] == 0) file.line_of[k] = file.line_of[k - 1];
  }

  std::string path_;
  ImportOptions options_;
  bool folder_known_;
  std::string folder_;          ///< the canonical folder of the file given
  std::string private_folder_;  ///< the rewritten copies, removed with this object
  int copies_ = 0;
  std::map<std::string, File> files_;  ///< by canonical path
  const File* main_ = nullptr;
  std::map<std::string, int> stripped_;  ///< elements without kinematic meaning removed, by name
  int renamed_world_joints_ = 0;
  std::optional<SourceLocation> zero_axis_;  ///< the first <xyz> of three zeros, for libsdformat's unlocated message
  std::unordered_map<std::string, SourceLocation> named_;  ///< "joint:j" -> where the first such element is
  std::vector<std::string> notices_;
};

class SdformatReader {
 public:
  SdformatReader(std::string path, const ModelFiles& files, const ImportOptions& options)
      : path_(std::move(path)), files_(files), options_(options) {}

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
    const bool world_joint = !grounded_.empty();
    if (!world_joint) grounded_ = ground_candidate_;
    builder.set_ground(grounded_);
    ImportedNetwork out{{}, files_.notices()};
    out.notices.push_back(fmt::format("{}: note: lengths in metres; joint limits, dynamics, inertia and geometry are not read "
                                      "(no kinematic meaning)", path_));
    if (world_joint) {
      out.notices.push_back(fmt::format("{}: note: base: a joint to the world holds the model; the world is the ground", path_));
    } else if (options_.base == ImportOptions::Base::floating) {
      builder.float_base(grounded_, {path_, 0, 0});
      out.notices.push_back(fmt::format("{}: note: base: no joint to the world: the canonical link '{}' floats (a free coupling "
                                        "to the world), as --base floating asks and as in Gazebo", path_, grounded_));
    } else {
      out.notices.push_back(fmt::format("{}: note: base: no joint to the world: the canonical link '{}' is the ground (kinestat's "
                                        "default; in Gazebo the model floats: --base floating)", path_, grounded_));
    }
    if (std::string loose = builder.mount_loose_groups(options_.base == ImportOptions::Base::fixed); !loose.empty())
      out.notices.push_back(std::move(loose));
    out.loaded = builder.finish();
    return out;
  }

 private:
  // libsdformat's messages span lines ("Error Code 9: Msg: ..."): one line for the report.
  static std::string one_line(std::string message) {
    for (char& c : message)
      if (c == '\n' || c == '\r') c = ' ';
    while (!message.empty() && message.back() == ' ') message.pop_back();
    return message;
  }

  // At the file and line the user knows (an included file's own), with libsdformat's words.
  // Errors of the frame graph carry no line: the element they name is found where it was written.
  [[noreturn]] void fail(const sdf::Error& error) const {
    const std::string message = one_line(files_.shown(error.Message()));
    SourceLocation at = files_.original(error.FilePath().value_or(""), error.LineNumber().value_or(0));
    if (at.line == 0)
      if (const auto named = files_.named_in(message)) at = *named;
    throw InputError(at, "libsdformat: " + message);
  }

  SourceLocation where(const sdf::ElementPtr& element) const {
    if (!element) return {path_, 0, 0};
    return files_.original(element->FilePath(), element->LineNumber().value_or(0));
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
                                                             "which a coupling network cannot express; remove the joint (its "
                                                             "two revolute joints then count the gear's motions separately)",
                                                             joint.Name()));
    }
    const std::string name = joint.Name() == kRenamedWorldJoint ? std::string("world") : joint.Name();
    builder.couple(scope + name, type, link(joint, true, scope), link(joint, false, scope), g, where(joint.Element()));
  }

  std::string path_;
  const ModelFiles& files_;
  ImportOptions options_;
  bool world_ = false;
  std::string grounded_, ground_candidate_;
};

}  // namespace

bool sdformat_reader_built_in() { return true; }

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
ImportedNetwork load(const std::string& path, const ModelFiles& files, ReadInto read_into, const sdf::Error& unreadable) {
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
  return SdformatReader(path, files, files.options()).read(root, errors);
}

}  // namespace

ImportedNetwork read_sdformat(const std::string& path, const ImportOptions& options) {
  ModelFiles files(path, options, true);
  const std::string read = files.prepare(read_text_file(path, options.max_input_bytes));  // the copy libsdformat reads
  return load(
      path, files,
      [&](const sdf::ParserConfig& config, const sdf::SDFPtr& document, sdf::Errors& errors) {
        return sdf::readFile(read, config, document, errors);
      },
      sdf::Error(sdf::ErrorCode::FILE_READ, "Unable to read file:" + path));
}

ImportedNetwork parse_sdformat(const std::string& path, const std::string& text) {
  ModelFiles files(path, {}, false);
  (void)files.prepare(text);  // refuses includes: text has no folder to resolve them in
  return load(
      path, files,
      [&](const sdf::ParserConfig& config, const sdf::SDFPtr& document, sdf::Errors& errors) {
        return sdf::readString(files.main_text(), config, document, errors);
      },
      sdf::Error(sdf::ErrorCode::STRING_READ, "Unable to read SDF string"));
}

#else

bool sdformat_reader_built_in() { return false; }

ImportedNetwork read_sdformat(const std::string& path, const ImportOptions&) {
  throw InputError({path, 0, 0}, "SDFormat is not built in: rebuild kinestat with libsdformat-dev and libtinyxml2-dev installed "
                                 "(docs/formats.md)");
}

ImportedNetwork parse_sdformat(const std::string& path, const std::string&) { return read_sdformat(path, {}); }

#endif

}  // namespace kinestat::io
