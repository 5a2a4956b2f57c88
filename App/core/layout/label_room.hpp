// SPDX-License-Identifier: LGPL-2.1-or-later
// Where a label's box may lie on a patch: what the patch id's placer (labels.cpp) and the
// partner ids' placer (partner_labels.cpp) share. Internal to the layout stage.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/region2d.hpp"
#include "layout/flat_patch.hpp"
#include "layout/labels.hpp"

namespace sliceform {

constexpr double kGap = 0.6;  // mm between labels, and between a label and its slot
// mm of paper between a leader and any cut: a laser's engraved line beside a cut needs no
// more, and a leader must pass where a label's box cannot.
constexpr double kLeaderMargin = 0.3;

// The paper a leader may cross: the patch less kLeaderMargin along every cut. Made when
// first asked, and kept in `paper` with the rooms asked of it.
const BoxRoom& leaderPaper(const LabelPaper& paper);

// Half the width and height of a label's box, turned a quarter when `vertical`.
Vec2 halfSize(const std::string& text, double height, bool vertical);

// The centres a box of half size `half` may have: the whole box inside `inner` (the paper
// eroded by the edge margin), `kGap` clear of the `taken` labels' boxes, not over any box
// of `keepOff` (a segment will do), and the centre inside `window`.
Region2d freeFor(const BoxRoom& inner, const std::vector<Label>& taken, Vec2 half, const Box2& window,
                 const std::vector<Box2>& keepOff = {});

// The point of `region` nearest to `p` (p itself when inside).
Vec2 nearestPoint(const Region2d& region, Vec2 p);

// The boxes of the leaders' segments of `labels`, for freeFor's keepOff: a label set later
// keeps off them (a segment's box will do).
std::vector<Box2> leaderBoxes(const std::vector<Label>& labels);

// The label of a slot that no label beside it or on its line reads as its own (a slot at
// a narrow tip, a line along the outline): in room within reach of the slot's root, joined
// to it by an engraved straight leader over `leaderRoom` (leaderPaper), crossing no label
// or leader in `taken`. Tried at `heights`, largest first; none when nothing is reached.
std::optional<Label> leaderLabel(const BoxRoom& inner, const BoxRoom& leaderRoom, const LabelSpot& s,
                                 const std::vector<Label>& taken, const std::vector<double>& heights);

// Whether a label may yet be found for a slot left without one, clear of `taken` or of any
// labels set after them: false only where surely none is. Every room the placer would try
// lies in a room asked here, and more labels only take room away.
// - leaderMayFit: leaderLabel at kMinLabelHeight, its box over `inner`.
// - besideMayFit: the last resort, a kMinLabelHeight label beside the slot or on its line
//   over `paper` (the leaders' paper), whatever other hinges it must keep off.
bool leaderMayFit(const BoxRoom& inner, const BoxRoom& leaderRoom, const LabelSpot& s,
                  const std::vector<Label>& taken);
bool besideMayFit(const BoxRoom& paper, const LabelSpot& s, const std::vector<Label>& taken);
// Whether any try may label `s` at all: false only where no label of any size, set any way
// (beside the slot, on its line, on a leader, the last resort), has room on the bare patch.
// labelPatch tries smaller patch ids only while a slot left without may yet be labelled.
bool mayEverFit(const LabelPaper& paper, const LabelSpot& s);

}  // namespace sliceform
