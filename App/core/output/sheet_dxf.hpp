// SPDX-License-Identifier: LGPL-2.1-or-later
// A sheet as DXF, for laser cutters and CAD programs that take DXF rather than SVG. DXF
// keeps the exact geometry: lines stay LINE, circular arcs ARC and holes CIRCLE, so the
// cutter follows true arcs instead of short chords. Cut paths go on layer CUT (red, ACI 1),
// labels on ENGRAVE (blue, ACI 5): the colours laser software maps to cut and engrave. The
// file is R2000 (AC1015) in millimetres ($INSUNITS 4), at true scale, with the sheet's
// bottom-left corner at the origin; it carries no sheet border, since everything on CUT
// is cut.
#pragma once

#include <string>

#include "layout/layout.hpp"

namespace sliceform {

// One DXF per sheet, written atomically. Throws Error(Io) when the file cannot be written.
void writeSheetDxf(const SheetDrawing& drawing, const SheetSpec& sheet, const std::string& path);

}  // namespace sliceform
