#include "kinestat/io/mjcf_reader.hpp"

#include <fmt/format.h>

#include <cctype>
#include <memory>
#include <regex>
#include <unordered_map>
#include <vector>

#include "kinestat/io/text_file.hpp"

#if KINESTAT_HAVE_MUJOCO
#include <mujoco/mujoco.h>
#endif

namespace kinestat::io {

#if KINESTAT_HAVE_MUJOCO

namespace {

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
/// in the working directory; kinestat collects the warnings as notices instead.
thread_local std::vector<std::string>* warnings = nullptr;
void collect_warning(const char* message) {
  if (warnings && warnings->size() < 16) warnings->push_back(message);
}

/// Largest mjData a model may ask for (stack plus buffer): mj_makeData ends the process when
/// an allocation fails, so a model asking for more is refused first.
constexpr double kMaxDataBytes = 1 << 30;

class MjcfReader {
 public:
  MjcfReader(std::string path, std::string text) : path_(std::move(path)), text_(std::move(text)) {}
  MjcfReader(const MjcfReader&) = delete;  // lines_ views text_
  MjcfReader& operator=(const MjcfReader&) = delete;

  ImportedNetwork read(mjModel* raw, const char* error) {
    if (!raw) {
      // MuJoCo's messages end with "Element 'x', line N" (sometimes a column too).
      std::string message = error;
      std::smatch match;
      int line = 0, column = 0;
      if (std::regex_search(message, match, std::regex("line (\\d+)"))) line = std::stoi(match[1]);
      if (std::regex_search(message, match, std::regex("column (\\d+)"))) column = std::stoi(match[1]);
      for (char& c : message)
        if (c == '\n') c = ' ';
      throw InputError({path_, line, line ? std::max(column, 1) : 0}, "MuJoCo: " + message);
    }
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
    std::string ignored;
    for (int e = 0; e < m->neq; ++e) {
      const std::string eq = name(m, mjOBJ_EQUALITY, e, "equality" + std::to_string(e));
      const int type = m->eq_type[e];
      if (type != mjEQ_CONNECT && type != mjEQ_WELD) {
        ignored += (ignored.empty() ? "" : ", ") + eq;
        continue;
      }
      if (!m->eq_active[e]) {
        ignored += (ignored.empty() ? "" : ", ") + eq + " (inactive)";
        continue;
      }
      const int b1 = m->eq_obj1id[e], b2 = m->eq_obj2id[e];
      JointGeometry g;
      if (type == mjEQ_CONNECT) {
        // The anchor is given in body 1's frame.
        const mjtNum* local = m->eq_data + mjNEQDATA * e;
        const mjtNum* x = d->xpos + 3 * b1;
        const mjtNum* r = d->xmat + 9 * b1;
        for (int i = 0; i < 3; ++i) g.point(i) = x[i] + r[3 * i] * local[0] + r[3 * i + 1] * local[1] + r[3 * i + 2] * local[2];
      } else {
        g.point = vec(d->xpos + 3 * b1);
      }
      builder.couple(eq, type == mjEQ_CONNECT ? screw::CouplingType::spherical : screw::CouplingType::rigid, body_name(m, b1),
                     body_name(m, b2), g, locate(eq));
    }
    ImportedNetwork out{builder.finish(), {}};
    for (const std::string& w : warnings_) out.notices.push_back(fmt::format("{}: note: MuJoCo: {}", path_, w));
    if (!ignored.empty())
      out.notices.push_back(fmt::format("{}: note: equality constraint(s) {} ignored: only active connect and weld "
                                        "constraints are kinematic couplings", path_, ignored));
    return out;
  }

 private:
  static Eigen::Vector3d vec(const mjtNum* v) { return {v[0], v[1], v[2]}; }

  static std::string name(const mjModel* m, int type, int id, const std::string& fallback) {
    const char* n = mj_id2name(m, type, id);
    return n && *n ? n : fallback;
  }

  static std::string body_name(const mjModel* m, int b) { return name(m, mjOBJ_BODY, b, b == 0 ? "world" : "body" + std::to_string(b)); }

  // MuJoCo keeps no file positions: the element is found by its name in the text. The first
  // place of every name="..." is indexed once, so that locating every joint stays linear.
  SourceLocation locate(const std::string& object) {
    if (!names_indexed_) index_names();
    const auto found = name_offsets_.find(object);
    if (found == name_offsets_.end()) return {path_, 0, 0};
    const std::size_t open = text_.rfind('<', found->second);
    const auto [line, column] = lines_.position(open == std::string::npos ? found->second : open);
    return {path_, line, column};
  }

  void index_names() {
    names_indexed_ = true;
    for (std::size_t at = text_.find("name="); at != std::string::npos; at = text_.find("name=", at + 5)) {
      if (at == 0 || !std::isspace(static_cast<unsigned char>(text_[at - 1])) || at + 5 >= text_.size()) continue;
      const char quote = text_[at + 5];
      if (quote != '"' && quote != '\'') continue;
      const std::size_t end = text_.find(quote, at + 6);
      if (end == std::string::npos) break;
      name_offsets_.emplace(text_.substr(at + 6, end - at - 6), at);
    }
  }

  std::string path_;
  std::string text_;
  LineIndex lines_{text_};
  bool names_indexed_ = false;
  std::unordered_map<std::string, std::size_t> name_offsets_;  ///< name -> offset of its first name="..."

 public:
  std::vector<std::string> warnings_;
};

// Loads through MuJoCo with its warnings collected into `reader`.
mjModel* load(const char* file, const mjVFS* vfs, char (&error)[1024], MjcfReader& reader) {
  warnings = &reader.warnings_;
  mju_user_warning = collect_warning;
  mjModel* m = mj_loadXML(file, vfs, error, sizeof error);
  warnings = nullptr;
  return m;
}

// MuJoCo 2.2.2's compiler takes time growing faster than the number of bodies (a flat model of
// 10^4 hinged bodies: 2.4 s; 2 * 10^4: 13 s; 10^5: 131 s), so larger models are refused before it
// starts. Counted on the text: a "<body" that is not "<body" inside another word.
constexpr std::size_t kMaxMjcfBodies = 10000;

void refuse_large(const std::string& path, const std::string& text) {
  std::size_t bodies = 0;
  for (std::size_t at = text.find("<body"); at != std::string::npos; at = text.find("<body", at + 5)) {
    const char next = at + 5 < text.size() ? text[at + 5] : '>';
    if (next == '>' || next == '/' || std::isspace(static_cast<unsigned char>(next))) ++bodies;
  }
  if (bodies > kMaxMjcfBodies)
    throw InputError({path, 0, 0}, fmt::format("the file has {} <body> elements; kinestat reads at most {} from an MJCF file, "
                                               "because MuJoCo 2.2.2's compiler takes time growing faster than their number "
                                               "(convert the model to URDF, which is read without this limit)",
                                               bodies, kMaxMjcfBodies));
}

// MuJoCo ends the process (mju_error, not an error message) on an empty file, and libmujoco
// 2.2.2 crashes on some malformed URDF, which it also reads: only an MJCF root reaches it (fuzzer).
void refuse_empty(const std::string& path, const std::string& text) {
  if (text.empty()) throw InputError({path, 0, 0}, "the file is empty: expected an MJCF model (<mujoco>)");
  if (xml_root_name(text) != "mujoco") throw InputError({path, 1, 1}, "expected an MJCF model: a <mujoco> root element");
  refuse_large(path, text);
}

}  // namespace

bool mjcf_reader_built_in() { return true; }

ImportedNetwork read_mjcf(const std::string& path) {
  const std::string text = read_text_file(path);
  refuse_empty(path, text);
  MjcfReader reader(path, text);
  char error[1024] = "";
  mjModel* m = load(path.c_str(), nullptr, error, reader);
  return reader.read(m, error);
}

ImportedNetwork parse_mjcf(const std::string& path, const std::string& text) {
  refuse_empty(path, text);
  const std::unique_ptr<mjVFS, VfsDeleter> vfs(new mjVFS);
  mj_defaultVFS(vfs.get());
  if (mj_makeEmptyFileVFS(vfs.get(), "model.xml", static_cast<int>(text.size())) != 0)
    throw InputError({path, 0, 0}, "MuJoCo: cannot hold the model in memory");
  const int index = mj_findFileVFS(vfs.get(), "model.xml");
  std::copy(text.begin(), text.end(), static_cast<char*>(vfs->filedata[index]));
  MjcfReader reader(path, text);
  char error[1024] = "";
  mjModel* m = load("model.xml", vfs.get(), error, reader);
  return reader.read(m, error);
}

#else

bool mjcf_reader_built_in() { return false; }

ImportedNetwork read_mjcf(const std::string& path) {
  throw InputError({path, 0, 0}, "MJCF is not built in: rebuild kinestat with libmujoco-dev installed (docs/formats.md)");
}

ImportedNetwork parse_mjcf(const std::string& path, const std::string&) { return read_mjcf(path); }

#endif

}  // namespace kinestat::io
