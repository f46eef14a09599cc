// SPDX-License-Identifier: BSD-3-Clause
#include "kinestat/report/verdict_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "kinestat/io/printable_text.hpp"
#include "kinestat/report/json_text.hpp"
#include "kinestat/report/rank_status_text.hpp"
#include "kinestat/tolerances.hpp"

namespace kinestat::report {

namespace {

using Json = nlohmann::ordered_json;
using io::printable_text;

// Participations to four digits (design::kParticipationScale, as they are ranked): enough to
// rank by eye, stable against last-bit noise.
double share(double x) { return std::round(x * design::kParticipationScale) / design::kParticipationScale; }

// Participants listed per state in the text report (fewer when there are more than two
// states), and states listed; JSON lists them all.
constexpr std::size_t kTextParticipants = 6;
constexpr std::size_t kTextParticipantsOfMany = 2;
constexpr std::size_t kTextStates = 3;
// Changes of one set listed in the text report; JSON lists them all.
constexpr std::size_t kTextChanges = 6;
// Lines of what the re-analysis compared (the counts, free bodies, one carrier) in the text.
constexpr std::size_t kTextChecks = 3;

Json participant_json(const design::Participant& p) {
  Json j;
  j["kind"] = p.kind;
  j["name"] = p.name;
  j["participation"] = share(p.participation);
  if (!p.detail.empty()) j["detail"] = p.detail;
  return j;
}

Json participants_json(const std::vector<design::Participant>& list) {
  Json out = Json::array();
  for (const auto& p : list) out.push_back(participant_json(p));
  return out;
}

std::string vector_text(const std::vector<double>& v) {
  std::vector<std::string> parts;
  for (double x : v) {
    std::string s = fmt::format("{:.6g}", std::abs(x) < kPrintedZero ? 0.0 : x);
    parts.push_back(s == "-0" ? "0" : s);
  }
  return fmt::format("({})", fmt::join(parts, ", "));
}

// Further verified change sets and turned-down sets listed in the text report; JSON lists them all.
constexpr std::size_t kTextAlternatives = 2;

// "T1a -> spherical" or "remove T3a": one change in a few words (for the alternatives).
std::string short_change_text(const design::DesignChange& c) {
  if (c.becomes == "removed") return fmt::format("remove {} {}", c.target_kind, printable_text(c.target));
  return fmt::format("{} {} -> {}", c.target_kind, printable_text(c.target), printable_text(c.becomes));
}

// Every string of the verdict can carry a name from the model: each is printed through
// io::printable_text.
std::string change_text(const design::DesignChange& c) {
  std::string text = fmt::format("{} {} {}", c.action, c.target_kind, printable_text(c.target));
  // "remove bar 5", "add bar E–G (a bar of length 2)", "release coupling J1: revolute -> spherical".
  if (c.becomes == "removed") {
  } else if (c.action == "add") {
    text += fmt::format(" ({})", printable_text(c.becomes));
  } else if (!c.from.empty()) {
    text += fmt::format(": {} -> {}", printable_text(c.from), printable_text(c.becomes));
  } else {
    text += fmt::format(" -> {}", printable_text(c.becomes));
  }
  std::vector<std::string> geometry;
  for (const auto& [key, value] : c.geometry)
    if (key != "point") geometry.push_back(fmt::format("{} {}", key, vector_text(value)));
  if (!geometry.empty()) text += fmt::format(" ({})", fmt::join(geometry, ", "));
  if (!c.reason.empty()) text += ": " + printable_text(c.reason);
  return text;
}

Json changes_json(const std::vector<design::DesignChange>& list) {
  Json changes = Json::array();
  for (const auto& c : list) {
    Json change;
    change["action"] = c.action;
    change["target_kind"] = c.target_kind;
    change["target"] = c.target;
    if (!c.from.empty()) change["from"] = c.from;
    change["becomes"] = c.becomes;
    if (!c.geometry.empty()) {
      Json geometry = Json::object();
      for (const auto& [key, value] : c.geometry) geometry[key] = value;
      change["geometry"] = geometry;
    }
    change["reason"] = c.reason;
    changes.push_back(change);
  }
  return changes;
}

}  // namespace

Json verdict_json(const design::Verdict& v) {
  Json j;
  j["exactly_constrained"] = v.exactly_constrained;
  j["extra_motions"] = v.extra_motions;
  j["redundant_constraints"] = v.redundant_constraints;
  j["summary"] = v.summary;
  j["intended_motions"] = v.intended_motions;
  j["intended_from"] = v.intended_basis;
  j["where"] = {{"extra_motions", participants_json(v.motion_participants)},
                {"redundant_constraints", participants_json(v.constraint_participants)}};
  Json states = Json::array();
  for (const auto& s : v.states)
    states.push_back({{"kind", s.kind}, {"description", s.description}, {"participants", participants_json(s.participants)}});
  j["states"] = states;
  j["changes"] = changes_json(v.changes);
  j["changes_verified"] = v.changes_verified;
  j["becomes"] = v.becomes;
  if (!v.verification.empty()) j["verification"] = v.verification;
  if (!v.alternatives.empty()) {
    Json alternatives = Json::array();
    for (const auto& set : v.alternatives) alternatives.push_back(changes_json(set));
    j["alternatives"] = alternatives;
  }
  if (!v.rejected.empty()) j["rejected"] = v.rejected;
  if (!v.note.empty()) j["note"] = v.note;
  if (!v.generic.empty()) j["special_geometry"] = v.generic;
  if (v.near_rank_change) j["near_rank_change"] = rank_evidence_number(*v.near_rank_change);
  if (v.geometric_counts && v.generic_counts) {
    j["geometric_counts"] = {{"FN", v.geometric_counts->freedoms}, {"CN", v.geometric_counts->constraints}};
    j["generic_counts"] = {{"FN", v.generic_counts->freedoms}, {"CN", v.generic_counts->constraints}};
  }
  return j;
}

Json lead_with_verdict(const design::Verdict& verdict, Json report, const std::string& units) {
  // Room for callers' further keys too (json_object: growing an object copies its values).
  Json j = json_object(report.size() + 16);
  j["verdict"] = verdict_json(verdict);
  if (!units.empty()) j["units"] = units;
  for (auto it = report.begin(); it != report.end(); ++it) j[it.key()] = std::move(it.value());
  add_versions(j);  // every report that leads with a verdict is a whole report: analyze, structure
  return j;
}

Json with_notices(Json report, const std::vector<std::string>& notices) {
  if (notices.empty() || !report.is_object()) return report;
  Json lines = Json::array();
  for (const std::string& notice : notices) lines.push_back(printable_text(notice));
  // A fixed place, so that the same input gives the same bytes: after the keys that lead.
  Json j = json_object(report.size() + 1);
  bool placed = false;
  for (auto it = report.begin(); it != report.end(); ++it) {
    if (!placed && it.key() != "verdict" && it.key() != "units") {
      j["notices"] = lines;
      placed = true;
    }
    j[it.key()] = std::move(it.value());
  }
  if (!placed) j["notices"] = std::move(lines);
  return j;
}

std::string verdict_text(const design::Verdict& v) {
  std::string t = fmt::format("Verdict: {}\n", printable_text(v.summary));
  // Where the structural count differs, one line with both counts takes the place of the
  // generic answer's sentences (they stay in the JSON and the detail): the block stays short.
  if (!v.geometric_counts || !v.generic_counts)
    for (const auto& sentence : v.generic) t += fmt::format("  generic: {}\n", printable_text(sentence));
  else
    t += fmt::format("  counts differ: FN = {}, CN = {} from the geometry; FN = {}, CN = {} by the structural (generic) count "
                     "the structural groups use\n",
                     v.geometric_counts->freedoms, v.geometric_counts->constraints, v.generic_counts->freedoms,
                     v.generic_counts->constraints);
  // The block stays short (issue 35: within 25 lines): a few states, fewer participants each
  // when there are many; the rest is in the JSON and the detail below.
  const std::size_t participants_shown = v.states.size() > 2 ? kTextParticipantsOfMany : kTextParticipants;  // the others: --json
  for (std::size_t k = 0; k < v.states.size(); ++k) {
    const auto& s = v.states[k];
    if (k == kTextStates) {
      std::size_t motions = 0;
      for (std::size_t m = k; m < v.states.size(); ++m) motions += v.states[m].kind == "extra motion" ? 1 : 0;
      t += fmt::format("  ... and {} more: {} extra motion(s), {} self-stress(es) (see --json)\n", v.states.size() - k, motions,
                       v.states.size() - k - motions);
      break;
    }
    // Participants left out without a line of their own are counted on the state's line.
    const bool counted_here = s.participants.size() > participants_shown && v.states.size() > 2;
    t += fmt::format("  {}: {}{}\n", s.kind, printable_text(s.description),
                     counted_here ? fmt::format(" ({} participants, {} shown; all in --json)", s.participants.size(), participants_shown) : "");
    for (std::size_t i = 0; i < s.participants.size() && i < participants_shown; ++i) {
      const auto& p = s.participants[i];
      t += fmt::format("    {:>3.0f}%  {} {}{}\n", 100.0 * p.participation, p.kind, printable_text(p.name),
                       p.detail.empty() ? "" : ": " + printable_text(p.detail));
    }
    if (s.participants.size() > participants_shown && v.states.size() <= 2)
      t += fmt::format("    ... and {} more (see --json)\n", s.participants.size() - participants_shown);
  }
  if (!v.changes.empty()) {
    t += fmt::format("  {} ({}):\n", v.changes.size() == 1 ? "change" : "changes",
                     v.changes_verified ? "one minimal set, verified by re-analysis" : "NOT verified: the re-analysis is not exactly constrained");
    for (std::size_t i = 0; i < v.changes.size() && i < kTextChanges; ++i) t += "    - " + change_text(v.changes[i]) + "\n";
    if (v.changes.size() > kTextChanges) t += fmt::format("    ... and {} more changes (see --json)\n", v.changes.size() - kTextChanges);
  }
  if (!v.becomes.empty() && !v.exactly_constrained) t += fmt::format("  becomes: {}\n", printable_text(v.becomes));
  for (std::size_t i = 0; i < v.verification.size() && i < kTextChecks; ++i)
    t += fmt::format("  {} {}{}\n", i == 0 ? "checked:" : "        ", printable_text(v.verification[i]),
                     i + 1 == kTextChecks && v.verification.size() > kTextChecks
                         ? fmt::format(" (and {} more, see --json)", v.verification.size() - kTextChecks)
                         : "");
  for (std::size_t i = 0; i < v.alternatives.size() && i < kTextAlternatives; ++i) {
    std::vector<std::string> parts;
    for (const auto& c : v.alternatives[i]) parts.push_back(short_change_text(c));
    t += fmt::format("  or instead (verified): {}\n", fmt::join(parts, ", "));
  }
  if (v.alternatives.size() > kTextAlternatives)
    t += fmt::format("  ... and {} more verified sets (see --json)\n", v.alternatives.size() - kTextAlternatives);
  for (std::size_t i = 0; i < v.rejected.size() && i < kTextAlternatives; ++i)
    t += fmt::format("  turned down: {}\n", printable_text(v.rejected[i]));
  if (v.rejected.size() > kTextAlternatives)
    t += fmt::format("  ... and {} more sets turned down (see --json)\n", v.rejected.size() - kTextAlternatives);
  if (!v.note.empty()) t += fmt::format("  note: {}\n", printable_text(v.note));
  t += "\n";
  return t;
}

}  // namespace kinestat::report
