// SPDX-License-Identifier: LGPL-2.1-or-later
#include "layout/layout.hpp"

#include <cmath>

#include "pipeline/design.hpp"

namespace sliceform {
namespace {

CutElement placed(CutElement e, const Placement& p) {
  // A rotation and a shift: arcs keep their sense and radius; their angles turn.
  e.a = p.apply(e.a);
  e.b = p.apply(e.b);
  e.centre = p.apply(e.centre);
  e.start += p.rotation * M_PI / 180;
  e.end += p.rotation * M_PI / 180;
  return e;
}

Stroke placed(const Stroke& s, const Placement& p) {
  Stroke out;
  for (const Vec2& q : s) out.push_back(p.apply(q));
  return out;
}

}  // namespace

SheetLayout layOut(const Design& design, const SheetSpec& sheet) {
  SheetLayout layout;
  layout.sheet = sheet;
  layout.patches = flattenPatches(design);
  std::vector<Region2d> outlines;
  std::vector<std::string> names;
  for (const FlatPatch& p : layout.patches) {
    outlines.push_back(p.outline);
    names.push_back(p.id);
  }
  layout.packing = nestOnSheets(outlines, names, sheet);
  layout.shelf = shelfPack(outlines, names, sheet);
  return layout;
}

std::vector<SheetDrawing> sheetDrawings(const SheetLayout& layout) {
  std::vector<SheetDrawing> sheets(layout.packing.sheets);
  for (size_t k = 0; k < layout.patches.size(); ++k) {
    const FlatPatch& patch = layout.patches[k];
    const Placement& at = layout.packing.placements[k];
    SheetDrawing& sheet = sheets[at.sheet];
    for (const CutLoop& loop : patch.cut) {
      CutLoop moved;
      for (const CutElement& e : loop) moved.push_back(placed(e, at));
      sheet.cut.push_back(moved);
    }
    for (const Stroke& s : patch.name.strokes) sheet.engrave.push_back(placed(s, at));
    for (const Label& l : patch.partners)
      for (const Stroke& s : l.strokes) sheet.engrave.push_back(placed(s, at));
  }
  return sheets;
}

}  // namespace sliceform
