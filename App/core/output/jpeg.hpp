// SPDX-License-Identifier: LGPL-2.1-or-later
// A picture as JPEG bytes (libjpeg), for cairo's PDF surface to embed as they are: cairo
// deflates every raw image as it closes a page, which was four fifths of the booklet's time.
#pragma once

#include <string>

#include "output/assembly_png.hpp"

namespace sliceform {

// Baseline JPEG of `picture` (0x00RRGGBB pixels) at `quality` (1–100), without chroma
// subsampling: the highlight's orange edges stay sharp. Throws Io if libjpeg fails.
std::string jpegBytes(const Picture& picture, int quality);

}  // namespace sliceform
