// SPDX-License-Identifier: LGPL-2.1-or-later
// Fewer points for polygons that carry more than their accuracy needs: mesh sections turn a
// degree or two at every triangle they cross.
#pragma once

#include "geometry/region2d.hpp"

namespace sliceform {

// The region with the points that lie within `tolerance` (mm) of the line through their
// neighbours left out: Douglas-Peucker on each loop (Boost.Geometry), then the loops
// filled even-odd again. Corners that turn by more stay; a loop thinner than the tolerance
// is kept as it was rather than lost.
Region2d simplified(const Region2d& region, double tolerance);

// Whether a loop (a hole, either way round) is a crumb, narrower than `width` all along:
// its area is under its perimeter times width / 2 (a strip w wide and L long has area wL,
// perimeter 2L + 2w). Where a slice grazes a surface, rounding leaves such holes of a few
// micrometres, often touching the outer loop: no hole to cut, and a face BRepCheck rejects.
bool isCrumb(const Region2d::Loop& hole, double width);

// The region with its crumb holes (isCrumb) filled; the region itself where it has none.
Region2d withoutCrumbs(const Region2d& region, double width);

}  // namespace sliceform
