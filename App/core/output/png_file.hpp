// SPDX-License-Identifier: LGPL-2.1-or-later
// PNG files of the pictures the CLI writes (sheets.png, assembly.png), by libpng directly:
// cairo's writer tries every row filter on every row and deflates at zlib's default level,
// a tenth of a mesh design's time for two preview pictures (fandisk).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace sliceform {

// Writes `height` rows of `width` pixels, 0x00RRGGBB each (row r at pixels + r * stride), as
// an 8-bit RGB PNG at `path`. Throws Io.
void writeRgbPng(const std::string& path, const uint32_t* pixels, int width, int height, size_t stride);

}  // namespace sliceform
