// SPDX-License-Identifier: LGPL-2.1-or-later
// Labels, engraved: the patch id well inside the patch and, at every hinge, the partner's id
// beside the slot, as in the paper's figures. Text is set in a small single-stroke font, so
// a laser engraves (or a plotter draws) one line per stroke and every output shows the
// same marks; a label is placed only where its whole box, plus a margin, is paper.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "geometry/region2d.hpp"
#include "layout/flat_patch.hpp"

namespace sliceform {

// The smallest cap height any label is engraved at, mm: still legible under a laser's or a
// fine pen's line (docs/decisions.md, "Labels are engraving").
constexpr double kMinLabelHeight = 1.0;

// The text as strokes, its box centred on `at`, cap height `height` mm.
Label setLabel(const std::string& text, Vec2 at, double height, bool vertical);
// Width of the text box at cap height `height`, mm.
double labelWidth(const std::string& text, double height);
// What a label's leader engraves: the leader itself, from the slot to the label, and an
// arrowhead at the slot.
std::vector<Stroke> leaderStrokes(const Stroke& leader);

// Where a hinge meets the patch, for its partner label.
struct LabelSpot {
  std::string text;  // the partner's id
  double x = 0;      // the hinge line
  Interval w;        // the hinge segment along it
  double y = 0;      // preferred height: beside the middle of the slot
  double slotWidth = 0;
  Interval slot;  // the slot's stretch of the line (a point, the root, where none is cut)
};

// Where a label's box may lie on a patch: its paper less a margin along every cut. Both
// placers start from it; a patch given to both computes it once.
// It keeps what the placers ask of it again and again: the rooms (BoxRoom), by cap height
// where a patch id's centre may lie at all (placeName), and the paper for leaders
// (leaderPaper). One patch's, one thread's.
struct LabelPaper {
  BoxRoom inner;
  Region2d paper;  // the patch itself, for leaders
  mutable std::map<double, Box2> nameWindows;
  mutable std::optional<BoxRoom> leaders;
};
LabelPaper labelPaper(const Region2d& paper);

// The sizes a patch id is tried at, largest first, mm.
const std::vector<double>& nameHeights();
// The patch id at the deepest spot that holds it (up to 8 mm high, and `maxHeight`),
// horizontal if it fits there, else upright, clear of `taken` labels; empty strokes when
// no box of 1 mm fits.
Label placeName(const LabelPaper& paper, const std::string& id, const std::vector<Label>& taken = {},
                double maxHeight = 8.0);
Label placeName(const Region2d& paper, const std::string& id);
// Partner labels at each slot, in spot order: beside it, across or turned along it, or on
// its hinge line beyond it; up to `maxHeight` (3.5 mm at most) and down to kMinLabelHeight;
// clear of each other and of `taken` labels. Spots with no room are left out and counted
// in `missing`.
std::vector<Label> placePartners(const LabelPaper& paper, const std::vector<LabelSpot>& spots,
                                 const std::vector<Label>& taken, double maxHeight, int& missing);
std::vector<Label> placePartners(const Region2d& paper, const std::vector<LabelSpot>& spots,
                                 const std::vector<Label>& taken, double maxHeight, int& missing);

// The patch's assembly step ("#5") beside its id: below it where there is room, else
// anywhere on the patch, up to half the id's height (3.5 mm at most) and down to 1 mm,
// clear of `taken` labels and their leaders; empty strokes when no box of 1 mm fits.
Label placeStep(const LabelPaper& paper, const std::string& text, const Label& name,
                const std::vector<Label>& taken);

// A patch's labels: its id, at each slot its partner's (placed again in other orders when a
// slot is left without; `missing` counts the slots left without one), and its assembly step
// when `step` > 0.
struct PatchLabels {
  Label name;
  std::vector<Label> partners;
  int missing = 0;
  Label step;
};
PatchLabels labelPatch(const LabelPaper& paper, const std::string& id, const std::vector<LabelSpot>& spots,
                       int step = 0);

}  // namespace sliceform
