// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Static SVG drawings of a scene, fit for a paper, with no external dependency. Layouts follow
// fixed placement rules and every number is written with fixed precision, so the same model
// gives byte-identical files.

#include <string>

#include "kinestat/report/scene.hpp"

namespace kinestat::report {

/// Coupling graph (seed 000, Fig. 2: bodies as nodes, couplings as directed edges, tree
/// branches thick, chords thin, circuits as arcs, cutsets as dashed cut lines) followed by
/// the motion graph (each coupling as f edges in series) and the action graph (c edges in
/// parallel) of Fig. 3. For structure models: the graph of bodies and pairs, coloured by
/// structural group.
std::string graph_svg(const Scene& scene);

struct MechanismDrawing {
  int mode = 1;    ///< 1-based mode drawn as arrows; 0: none
  int stress = 1;  ///< 1-based self-stress drawn as colours; 0: none
};

/// The model in its configuration: planar models in the xy-plane, spatial ones in a fixed
/// axonometric view; the verdict (or the classification) under the title; fixed, pinned and
/// roller supports (rollers with their free direction); rigid bodies as wide light bands,
/// flexures as thin dark lines; node and element labels; axes and a scale bar in the model's
/// length unit. A kinematic mode: the undeformed shape in grey, the displaced shape and nodal
/// arrows, and for networks the twist axis of every moving body. A self-stress: each element
/// coloured by its dominant generalised stress resultant (elongation by sign, tension positive
/// red, compression blue; bending, torsion, rigid-body constraint by hue; width by magnitude),
/// for networks the wrench axis of every coupling. Signs are the scene's, i.e. the analysis'.
/// Stressed lines carry data-element / data-kind / data-value attributes and mode arrows
/// data-node, so tests can read what is drawn. Above kLargeSceneElements elements the drawing
/// is one merged path without labels, arrows or glyphs.
std::string mechanism_svg(const Scene& scene, const MechanismDrawing& drawing = {});

}  // namespace kinestat::report
