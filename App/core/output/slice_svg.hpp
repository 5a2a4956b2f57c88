// SPDX-License-Identifier: LGPL-2.1-or-later
// A slice set drawn as one SVG sheet in millimetres: every slice at true scale in a grid,
// labelled with its number, position and area. A picture to check the slicing by eye.
#pragma once

#include <string>

#include "slicing/slice_set.hpp"

namespace sliceform {

void writeSliceSetSvg(const SliceSet& set, const std::string& title, const std::string& path);

}  // namespace sliceform
