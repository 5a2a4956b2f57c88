// SPDX-License-Identifier: LGPL-2.1-or-later
// A patch laid flat: its cut paths and engraving in the patch plane's own 2D coordinates
// (x along the plane's x_axis, y along its y_axis, mm; the same coordinates as report.json's
// outlines). Cut paths keep the exact faces' lines and circular arcs, so a DXF can carry
// ARC and CIRCLE entities; other curves are sampled within kOutlineDeflection.
#pragma once

#include <string>
#include <vector>

#include "arrangement/arrange.hpp"
#include "exact/patch_faces.hpp"
#include "frames/scaffold.hpp"
#include "geometry/region2d.hpp"
#include "realization/realize.hpp"

namespace sliceform {

// What the layout reads of a design, as realizationInput() narrows the arrangement for the
// realization (pipeline/design.hpp: layoutInput()): the arrangement (patch ids, planes and
// frames), the realization (slots, assembly order, kerf), which scaffold hinges the emitted
// patches still meet (Emitted::meets), and the patches' faces. It refers to them: the
// design must outlive it.
struct LayoutInput {
  const Arrangement& arrangement;
  const Realization& realization;
  const std::vector<char>& meets;
  const std::vector<PatchFace>& patches;
};

// One piece of a cut loop, in the loop's direction: a segment from `a` to `b`, an arc
// from angle `start` to `end` about `centre` (counter-clockwise when `ccw`, radians), or a
// full circle.
struct CutElement {
  enum class Kind { Line, Arc, Circle } kind = Kind::Line;
  Vec2 a, b;  // end points (for an arc too: a at `start`, b at `end`)
  Vec2 centre;
  double radius = 0, start = 0, end = 0;
  bool ccw = true;
};
using CutLoop = std::vector<CutElement>;  // closed and connected, in order

// An engraved polyline (labels).
using Stroke = std::vector<Vec2>;

// A label: text set in strokes, and the box it occupies (for the report and the tests).
struct Label {
  std::string text;
  Vec2 at;                      // centre of the text box
  double height = 0;            // mm, cap height
  bool vertical = false;        // rotated 90° (reads bottom to top)
  std::vector<Stroke> strokes;  // the text's and, last, the leader's
  Stroke leader;                // from the slot to the box, where the label stands off; or empty
};

// A slot left without a partner label: the partner's id, and where the booklet marks it on
// the hinge line: the middle of the slot's stretch, or the root for a slot cut through (and
// for a hinge this patch leaves uncut, where the partner's slot goes through).
struct UnlabelledSlot {
  std::string partner;
  Vec2 at;
};

struct FlatPatch {
  int patch = -1;
  std::string id;  // "U3", "V7"
  Family family = Family::U;
  std::vector<CutLoop> cut;                // outer loops and holes (slots already cut), kerf applied
  Region2d outline;                        // the paper, polygonised (kOutlineDeflection)
  Label name;                              // the patch id, well inside the patch
  std::vector<Label> partners;             // the partner's id beside each slot
  std::vector<UnlabelledSlot> unlabelled;  // the slots with no room for a partner label
  int partnersOnLeaders = 0;               // partner labels that stand off, with a leader to their slot
  int step = 0;                            // its place in the assembly order, 1-based (0: none)
  Label stepLabel;                         // "#step" beside the id (no strokes when it has no room)
};

// One patch of a design laid flat and labelled (patch: an index into input.patches); the
// kerf moves the cut paths as SlotParams::kerf says (outline and labels stay the paper's).
// Patches are independent of each other.
FlatPatch flattenPatch(const LayoutInput& input, int patch);

// An arc's sweep, radians, in (0, 2 pi) the way it turns.
double sweepOf(const CutElement& e);
// A point of a cut element at parameter t in [0, 1] (used for sampling and bounds).
Vec2 pointAt(const CutElement& e, double t);
// The element sampled within `deflection` mm, its first point included, its last not.
std::vector<Vec2> sample(const CutElement& e, double deflection);

}  // namespace sliceform
