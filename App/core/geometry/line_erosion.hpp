// SPDX-License-Identifier: LGPL-2.1-or-later
// Where a region eroded by a disc meets vertical lines, without eroding the region: what the
// hinge table asks of every cylinder's section on every line of the other family.
#pragma once

#include <vector>

#include "geometry/region2d.hpp"

namespace sliceform {

// region.offset(-delta).intervalsOnVerticalLines(xs), from `full` =
// region.intervalsOnVerticalLines(xs): a point of the region lies in the erosion when no edge
// comes nearer than delta, and the points of the line x = c nearer than delta to an edge
// form one interval (the line across the edge's capsule, which is convex). So each line's
// intervals less those near an edge are the erosion's, exactly. offset() cuts round corners
// as chords within its arc tolerance (1 µm) and rounds to Clipper's units: its intervals end
// up to that much apart from these, and further where a line grazes a round corner (the
// chord meets it elsewhere along the arc); tests/core/region2d_test.cpp.
std::vector<std::vector<Interval>> erodedOnVerticalLines(const Region2d& region,
                                                         const std::vector<double>& xs,
                                                         const std::vector<std::vector<Interval>>& full,
                                                         double delta);

}  // namespace sliceform
