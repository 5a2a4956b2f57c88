// SPDX-License-Identifier: LGPL-2.1-or-later
#include "layout/layout.hpp"

#include <cmath>
#include <exception>

#include "layout/cut_paths.hpp"
#include "layout/labels.hpp"
#include "support/parallel.hpp"

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

std::vector<const Label*> labelsOf(const FlatPatch& patch) {
  std::vector<const Label*> labels{&patch.name};
  for (const Label& l : patch.partners) labels.push_back(&l);
  if (patch.stepLabel.height > 0) labels.push_back(&patch.stepLabel);
  return labels;
}

// A label set again at its placed centre so it reads upright on the sheet: a patch turned
// half round would otherwise show "V3" as "EΛ". Placements turn by quarters, so the label's
// box is the same box, a quarter turn swapping horizontal and vertical.
Label upright(const Label& l, const Placement& at) {
  const bool quarter = std::lround(at.rotation / 90) % 2 != 0;
  Label u = setLabel(l.text, at.apply(l.at), l.height, l.vertical != quarter);
  for (const Vec2& p : l.leader) u.leader.push_back(at.apply(p));
  for (Stroke& s : leaderStrokes(u.leader)) u.strokes.push_back(std::move(s));
  return u;
}

// What nesting reads of the patches: their outlines and ids.
struct Nestable {
  std::vector<Region2d> outlines;
  std::vector<std::string> names;
};

Nestable nestable(const LayoutInput& input) {
  Nestable n;
  for (size_t k = 0; k < input.patches.size(); ++k) {
    n.outlines.push_back(input.patches[k].outline);
    n.names.push_back(patchId(input.arrangement.scaffold, static_cast<int>(k)));
  }
  return n;
}

}  // namespace

SheetLayout layOut(const LayoutInput& input, const SheetSpec& sheet) {
  SheetLayout layout;
  layout.sheet = sheet;
  layout.kerf = input.realization.params.kerf;
  const Nestable n = nestable(input);
  // Nesting reads only the outlines, not the labels: it is one more task beside the
  // patches, handed out first (it takes longest), so one core nests while the others
  // flatten and label the patches. Every task writes its own slot: the result does not
  // depend on the schedule. A flattening error still comes first, as when nesting followed.
  layout.patches.resize(input.patches.size());
  std::exception_ptr nestFailure;
  parallelFor(layout.patches.size() + 1, [&](size_t task) {
    if (task > 0) {
      layout.patches[task - 1] = flattenPatch(input, static_cast<int>(task - 1));
      return;
    }
    try {
      layout.packing = nestOnSheets(n.outlines, n.names, sheet);
    } catch (...) {
      nestFailure = std::current_exception();
    }
  });
  if (nestFailure) std::rethrow_exception(nestFailure);
  layout.shelf = shelfPack(n.outlines, n.names, sheet);
  return layout;
}

SheetLayout laidOutAgain(const LayoutInput& input, const SheetLayout& laid, const SheetSpec& sheet) {
  SheetLayout layout = laid;
  const SheetSpec& was = laid.sheet;
  if (sheet.name != was.name || sheet.width != was.width || sheet.height != was.height ||
      sheet.margin != was.margin || sheet.spacing != was.spacing || sheet.rotate != was.rotate) {
    const Nestable n = nestable(input);
    layout.sheet = sheet;
    layout.packing = nestOnSheets(n.outlines, n.names, sheet);
    layout.shelf = shelfPack(n.outlines, n.names, sheet);
  }
  if (input.realization.params.kerf != laid.kerf) {
    layout.kerf = input.realization.params.kerf;
    parallelFor(layout.patches.size(),
                [&](size_t k) { layout.patches[k].cut = cutPaths(input, layout.patches[k].patch); });
  }
  return layout;
}

SheetDrawing placedDrawing(const FlatPatch& patch, const Placement& at) {
  SheetDrawing drawing;
  for (const CutLoop& loop : patch.cut) {
    CutLoop moved;
    for (const CutElement& e : loop) moved.push_back(placed(e, at));
    drawing.cut.push_back(moved);
  }
  for (const Label* l : labelsOf(patch))
    for (const Stroke& s : upright(*l, at).strokes) drawing.engrave.push_back(s);
  return drawing;
}

std::vector<SheetDrawing> sheetDrawings(const SheetLayout& layout) {
  std::vector<SheetDrawing> sheets(layout.packing.sheets);
  for (size_t k = 0; k < layout.patches.size(); ++k) {
    const Placement& at = layout.packing.placements[k];
    SheetDrawing patch = placedDrawing(layout.patches[k], at);
    SheetDrawing& sheet = sheets[at.sheet];
    sheet.cut.insert(sheet.cut.end(), patch.cut.begin(), patch.cut.end());
    sheet.engrave.insert(sheet.engrave.end(), patch.engrave.begin(), patch.engrave.end());
  }
  return sheets;
}

}  // namespace sliceform
