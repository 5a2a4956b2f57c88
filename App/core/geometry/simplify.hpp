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

}  // namespace sliceform
