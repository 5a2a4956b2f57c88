// SPDX-License-Identifier: LGPL-2.1-or-later
// The sheets drawn with cairo, all at true scale in millimetres: a multi-page PDF to print
// at 100 % (each page carries a 50 mm scale bar in its margin to check the printer did not
// scale), one SVG per sheet for laser cutters (width and height in mm, viewBox in mm, so no
// 72/96 dpi guessing), and a PNG preview of every sheet side by side. Cut lines are red,
// engraving blue, as laser software expects; each file is written atomically.
#pragma once

#include <string>
#include <vector>

#include "layout/layout.hpp"

namespace sliceform {

void writeSheetsPdf(const std::vector<SheetDrawing>& sheets, const SheetSpec& spec, const std::string& path);
void writeSheetSvg(const SheetDrawing& sheet, const SheetSpec& spec, const std::string& path);
void writeSheetsPng(const std::vector<SheetDrawing>& sheets, const SheetSpec& spec, const std::string& path,
                    double pixelsPerMm = 2);

}  // namespace sliceform
