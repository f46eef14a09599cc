// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The interactive report: one self-contained HTML file (three.js, the viewer and the scene as
// JSON inlined) that opens offline in any browser with WebGL.

#include <nlohmann/json.hpp>

#include <string>

#include "kinestat/report/scene.hpp"

namespace kinestat::report {

/// True when this build embeds the viewer (npm was available when kinestat was built).
bool html_report_built_in();

/// The scene as the viewer reads it. Numbers are rounded to 6 significant decimals of the
/// model size, so files are deterministic and compact. Large scenes (Scene::large) carry no
/// names, glyphs, modes or stresses.
nlohmann::ordered_json scene_json(const Scene& scene);

/// The HTML document. Requires html_report_built_in(). `figure` (optional) is an SVG document
/// shown in the side panel under `figure_title`, e.g. the coupling graph or structural diagram.
std::string html_report(const Scene& scene, const std::string& figure = {}, const std::string& figure_title = {});

}  // namespace kinestat::report
