// SPDX-License-Identifier: LGPL-2.1-or-later
// A patch's cut paths (FlatPatch::cut): its faces' boundaries in the patch plane's 2D
// coordinates as lines and arcs, moved away from the paper by half the kerf where there is
// one. Internal to the layout stage.
#pragma once

#include <vector>

#include "layout/flat_patch.hpp"

namespace sliceform {

// Patch `patch`'s cut paths, the kerf (input.realization.params.kerf) applied: OCCT's offset
// of an exact face of lines and circles, its corners that turn less than 120° mitred; the
// paper's polygon moved out by Clipper for a polygon patch, an exact face with other curves,
// or where OCCT's offset fails (docs/decisions.md, Kerf).
std::vector<CutLoop> cutPaths(const LayoutInput& input, int patch);

}  // namespace sliceform
