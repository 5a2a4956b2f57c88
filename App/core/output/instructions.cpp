// SPDX-License-Identifier: LGPL-2.1-or-later
#include "output/instructions.hpp"

#include <cairo-pdf.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <new>

#include "output/cairo_file.hpp"
#include "output/jpeg.hpp"
#include "support/atomic_file.hpp"
#include "support/error.hpp"

namespace sliceform {
namespace {

constexpr double kPointsPerMm = 72 / 25.4;
constexpr double kPageW = 210, kPageH = 297, kMargin = 15;  // A4 portrait, mm
constexpr int kColumns = 2;
constexpr int kPictureWidth = 280;  // pixels of a step picture: 80 mm at about 90 dpi
// Flat colours and thin edges: at 85 without chroma subsampling no ringing shows at print
// size (at 92 the booklet grew by half again for no difference one can see). The booklet
// is about a fifth larger than with cairo's deflated pictures (ChineseDragon 2.7 against
// 2.2 MB) and takes half the time.
constexpr int kJpegQuality = 85;
// A step's cell below its text: the assembly picture takes this share of the width, the
// patch the rest; the patch is turned a quarter more when that draws it this much larger.
constexpr double kPictureShare = 0.62, kTurnGain = 1.3;

using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;

std::string joined(const std::vector<std::string>& ids) {
  std::string out;
  for (const std::string& id : ids) out += (out.empty() ? "" : ", ") + id;
  return out;
}

// A picture on the page, fitted into w x h mm with its top-left at (x, y).
void drawPicture(cairo_t* cr, const Picture& p, double x, double y, double w, double h) {
  // The picture's own pixels, not a copy in a surface cairo makes (and zeroes first): a
  // picture's rows are as long as cairo asks for RGB24 (4 bytes a pixel, a multiple of 4).
  static_assert(sizeof(uint32_t) == 4);
  const Surface image(cairo_image_surface_create_for_data(
                          reinterpret_cast<unsigned char*>(const_cast<uint32_t*>(p.pixels.data())),
                          CAIRO_FORMAT_RGB24, p.width, p.height, p.width * 4),
                      cairo_surface_destroy);
  // The PDF carries the JPEG as it is (cairo deflates a raw image, which cost four fifths of
  // the booklet); the picture's pixels stay for any other surface. cairo frees the copy.
  const std::string jpeg = jpegBytes(p, kJpegQuality);
  auto* bytes = static_cast<unsigned char*>(std::malloc(jpeg.size()));
  if (!bytes) throw std::bad_alloc();
  std::copy(jpeg.begin(), jpeg.end(), bytes);
  if (cairo_surface_set_mime_data(image.get(), CAIRO_MIME_TYPE_JPEG, bytes, jpeg.size(), std::free, bytes) !=
      CAIRO_STATUS_SUCCESS)
    std::free(bytes);
  const double scale = std::min(w / p.width, h / p.height);
  cairo_save(cr);
  cairo_translate(cr, x + (w - p.width * scale) / 2, y);
  cairo_scale(cr, scale, scale);
  cairo_set_source_surface(cr, image.get(), 0, 0);
  cairo_paint(cr);
  cairo_restore(cr);
}

void highlightColour(cairo_t* cr) {
  cairo_set_source_rgb(cr, ((kHighlight >> 16) & 255) / 255.0, ((kHighlight >> 8) & 255) / 255.0,
                       (kHighlight & 255) / 255.0);
}

// Boxes on the page (mm), for keeping the marks' ids apart.
struct PageBox {
  double x0, y0, x1, y1;
  bool overlaps(const PageBox& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

// A dot in the highlight colour at each mark and its id beside it. Marks a few millimetres
// apart drew their ids over each other's dots ("U6" under "U7"'s): each id takes the first
// place that is free of the dots and of the ids already set, beside its dot, then above or
// below it, then further up or down with a thin line back to the dot.
void drawMarks(cairo_t* cr, const std::vector<std::pair<std::string, Vec2>>& marks) {
  constexpr double kSize = 2.6, kGap = 0.4;
  // Dots of 1.2 mm radius, smaller (down to 0.5 mm) where marks are closer than 3 mm, so
  // two dots do not run into one.
  double dot = 1.2;
  for (size_t i = 0; i < marks.size(); ++i)
    for (size_t j = i + 1; j < marks.size(); ++j)
      dot = std::max(0.5, std::min(dot, 0.4 * std::hypot(marks[i].second.x - marks[j].second.x,
                                                         marks[i].second.y - marks[j].second.y)));
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  cairo_set_font_size(cr, kSize);
  highlightColour(cr);
  std::vector<PageBox> taken;
  for (const auto& [id, q] : marks) {
    cairo_arc(cr, q.x, q.y, dot, 0, 2 * M_PI);
    cairo_fill(cr);
    taken.push_back({q.x - dot, q.y - dot, q.x + dot, q.y + dot});
  }
  std::vector<size_t> order(marks.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return marks[a].second.y < marks[b].second.y; });
  for (size_t i : order) {
    const auto& [id, q] = marks[i];
    cairo_text_extents_t extents;
    cairo_text_extents(cr, id.c_str(), &extents);
    const double w = extents.x_advance, h = kSize * 0.75;  // cap height
    // Baseline-left corners to try: right, left, above, below, then right and left of the
    // dot one line further up or down at a time.
    std::vector<Vec2> tries{{q.x + dot + kGap, q.y + h / 2},
                            {q.x - dot - kGap - w, q.y + h / 2},
                            {q.x - w / 2, q.y - dot - kGap},
                            {q.x - w / 2, q.y + dot + kGap + h}};
    for (int k = 1; k <= 6; ++k)
      for (const int side : {1, -1})
        for (const double dx : {dot + kGap, -dot - kGap - w})
          tries.push_back({q.x + dx, q.y + h / 2 + side * k * (h + kGap)});
    Vec2 at = tries.front();
    for (const Vec2& t : tries) {
      const PageBox box{t.x - kGap / 2, t.y - h - kGap / 2, t.x + w + kGap / 2, t.y + kGap / 2};
      if (std::none_of(taken.begin(), taken.end(), [&](const PageBox& b) { return b.overlaps(box); })) {
        at = t;
        break;
      }
    }
    taken.push_back({at.x, at.y - h, at.x + w, at.y});
    if (std::fabs(at.y - (q.y + h / 2)) > 1e-9 && std::fabs(at.x - (q.x - w / 2)) > 1e-9) {
      // Moved up or down: a hairline from the dot to the id's nearer end.
      const double endX = at.x > q.x ? at.x : at.x + w;
      cairo_set_line_width(cr, 0.15);
      cairo_move_to(cr, q.x, q.y);
      cairo_line_to(cr, endX, at.y - h / 2);
      cairo_stroke(cr);
    }
    cairo_move_to(cr, at.x, at.y);
    cairo_show_text(cr, id.c_str());
  }
}

// The step's patch turned by `rotationDegrees` (as placed on its sheet, or a quarter more),
// and its bounds, mm.
struct FlatView {
  SheetDrawing drawing;
  Placement turn;
  Box2 box;
  // The scale that fits it into w x h mm; turned a quarter more, its box is the same with
  // width and height swapped.
  double scaleIn(double w, double h, bool quarterMore = false) const {
    const double bw = box.max.x - box.min.x + 1e-9, bh = box.max.y - box.min.y + 1e-9;
    return quarterMore ? std::min(w / bh, h / bw) : std::min(w / bw, h / bh);
  }
};

FlatView flatView(const FlatPatch& flat, double rotationDegrees) {
  FlatView v{{}, Placement{0, {0, 0}, rotationDegrees}, {}};
  v.drawing = placedDrawing(flat, v.turn);
  Box2& box = v.box;
  for (const CutLoop& loop : v.drawing.cut)
    for (const CutElement& e : loop)
      for (const Vec2& q : sample(e, 0.5)) {
        box.min = box.empty ? q : Vec2{std::min(box.min.x, q.x), std::min(box.min.y, q.y)};
        box.max = box.empty ? q : Vec2{std::max(box.max.x, q.x), std::max(box.max.y, q.y)};
        box.empty = false;
      }
  return v;
}

// The patch fitted into w x h mm at (x, y): its outline and slots in grey, and at each slot
// that goes onto a partner in this step a dot in the highlight colour with that partner's
// id, where its partner label is engraved (or on the slot, where it has none): whoever
// assembles matches the picture's slots with the paper in hand.
void drawFlatPatch(cairo_t* cr, const FlatPatch& flat, const FlatView& view,
                   const std::vector<std::string>& onto, double x, double y, double w, double h) {
  const SheetDrawing& drawing = view.drawing;
  const Placement& turn = view.turn;
  const Box2& box = view.box;
  if (box.empty || w <= 0 || h <= 0) return;
  const double scale = view.scaleIn(w, h);
  // Sheet millimetres (y up) to the page (y down), centred in the box.
  const double left = x + (w - (box.max.x - box.min.x) * scale) / 2;
  const auto page = [&](Vec2 q) {
    return Vec2{left + (q.x - box.min.x) * scale, y + (box.max.y - q.y) * scale};
  };
  cairo_save(cr);
  cairo_set_line_width(cr, 0.2);
  cairo_set_source_rgb(cr, 0.45, 0.45, 0.45);
  for (const CutLoop& loop : drawing.cut) {
    for (const CutElement& e : loop) {
      const std::vector<Vec2> points = sample(e, 0.2 / scale);
      for (size_t i = 0; i < points.size(); ++i) {
        const Vec2 q = page(points[i]);
        (i == 0 && &e == &loop.front() ? cairo_move_to : cairo_line_to)(cr, q.x, q.y);
      }
    }
    cairo_close_path(cr);
    cairo_stroke(cr);
  }
  // Every slot the step names: where its partner label is engraved, or, where the sheet had
  // no room for one, on the slot itself (the maker writes the id there).
  std::vector<std::pair<std::string, Vec2>> marks;
  for (const Label& l : flat.partners)
    if (std::find(onto.begin(), onto.end(), l.text) != onto.end())
      marks.emplace_back(l.text, page(turn.apply(l.at)));
  for (const UnlabelledSlot& slot : flat.unlabelled)
    if (std::find(onto.begin(), onto.end(), slot.partner) != onto.end())
      marks.emplace_back(slot.partner, page(turn.apply(slot.at)));
  drawMarks(cr, marks);
  cairo_restore(cr);
}

// Text at (x, y) mm (baseline), `size` mm high; returns the next line's baseline. Lines
// longer than `width` mm are broken at spaces.
double text(cairo_t* cr, const std::string& s, double x, double y, double size, double width,
            bool bold = false) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  std::string line;
  const auto flush = [&] {
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, line.c_str());
    y += size * 1.35;
    line.clear();
  };
  size_t at = 0;
  while (at < s.size()) {
    size_t next = s.find(' ', at);
    if (next == std::string::npos) next = s.size();
    const std::string word = s.substr(at, next - at);
    const std::string tried = line.empty() ? word : line + " " + word;
    cairo_text_extents_t e;
    cairo_text_extents(cr, tried.c_str(), &e);
    if (e.x_advance > width && !line.empty()) {
      flush();
      line = word;
    } else {
      line = tried;
    }
    at = next + 1;
  }
  if (!line.empty()) flush();
  return y;
}

void cover(cairo_t* cr, const Design& d, const Picture& whole, const std::string& title) {
  const double width = kPageW - 2 * kMargin;
  double y = text(cr, "Sliceform: " + title, kMargin, kMargin + 8, 8, width, true);
  const double h = std::min(130.0, width * whole.height / whole.width);
  drawPicture(cr, whole, kMargin, y, width, h);
  y += h + 8;
  const Scaffold& s = d.arrangement.scaffold;
  int u = 0;
  for (const ScaffoldPatch& p : s.patches) u += p.family == Family::U ? 1 : 0;
  const SheetLayout& l = d.layout;
  y = text(cr,
           std::to_string(s.patches.size()) + " patches (" + std::to_string(u) + " U, " +
               std::to_string(s.patches.size() - u) + " V) on " + std::to_string(l.packing.sheets) + " " +
               l.sheet.name + " sheet(s), in " + std::to_string(assemblySteps(d).size()) + " steps.",
           kMargin, y, 4, width);
  y = text(cr, "Parts by sheet", kMargin, y + 3, 4.5, width, true);
  for (int sheet = 0; sheet < l.packing.sheets; ++sheet) {
    std::vector<std::string> ids;
    for (size_t k = 0; k < l.patches.size(); ++k)
      if (l.packing.placements[k].sheet == sheet) ids.push_back(l.patches[k].id);
    y = text(cr, "Sheet " + std::to_string(sheet + 1) + ": " + joined(ids), kMargin, y, 3.5, width);
  }
  y = text(cr, "Tools", kMargin, y + 3, 4.5, width, true);
  y = text(cr,
           "A laser cutter, or a sharp knife, a steel ruler and a cutting mat. No glue: the slots hold it. "
           "Cut along the red lines; the blue ids are engraved or drawn, not cut.",
           kMargin, y, 3.5, width);
  y = text(cr, "How", kMargin, y + 3, 4.5, width, true);
  text(
      cr,
      "Cut every patch first and keep the ids readable; the number engraved beside each id (#5) is its "
      "step. Then follow the steps: each adds one patch, orange "
      "in its picture. Its slots open at the top or at the bottom; slide it on so each slot meets the named "
      "partner's slot, until the slots' ends touch. Check the ids at each slot (the partner's id is engraved "
      "beside it; where the sheet had no room, the step's drawing marks the slot: write the id there) "
      "before you push.",
      kMargin, y, 3.5, width);
}

}  // namespace

std::vector<AssemblyStep> assemblySteps(const Design& d) {
  const Scaffold& s = d.arrangement.scaffold;
  const std::vector<int>& order = d.realization.assemblyOrder;
  std::vector<bool> placed(s.patches.size(), false);
  std::vector<AssemblyStep> steps;
  for (const int k : order) {
    AssemblyStep step;
    step.patch = k;
    step.id = patchId(s, k);
    for (size_t h = 0; h < s.hinges.size(); ++h) {
      const ScaffoldHinge& hinge = s.hinges[h];
      if (!d.emitted.meets[h] || (hinge.u != k && hinge.v != k)) continue;
      const int partner = hinge.u == k ? hinge.v : hinge.u;
      if (!placed[partner]) continue;
      const Slot mine = hinge.u == k ? uSlot(d.realization.slots[h]) : vSlot(d.realization.slots[h]);
      const std::string id = patchId(s, partner);
      auto& into = mine == Slot::Up        ? step.fromTop
                   : mine == Slot::Down    ? step.fromBottom
                   : mine == Slot::Through ? step.through
                                           : step.partnerCuts;
      if (std::find(into.begin(), into.end(), id) == into.end()) into.push_back(id);
    }
    placed[k] = true;
    steps.push_back(std::move(step));
  }
  return steps;
}

void writeInstructionsPdf(const Design& d, const std::vector<Panel3>& panels, const Picture& whole,
                          const std::string& title, const std::string& path) {
  const std::vector<AssemblyStep> steps = assemblySteps(d);
  std::vector<int> panelOf(d.patches.size(), -1), flatIndex(d.patches.size(), -1);
  for (size_t k = 0; k < d.layout.patches.size(); ++k)
    flatIndex[d.layout.patches[k].patch] = static_cast<int>(k);
  for (size_t i = 0; i < panels.size(); ++i)
    if (panels[i].patch >= 0) panelOf[panels[i].patch] = static_cast<int>(i);
  writeAtomically(path, [&](const std::string& temporary) {
    cairo_surface_t* surface =
        cairo_pdf_surface_create(temporary.c_str(), kPageW * kPointsPerMm, kPageH * kPointsPerMm);
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "Sliceform");
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, ("Assembling " + title).c_str());
    drawAndFinish(surface, path, [&](cairo_t* cr) {
      cairo_scale(cr, kPointsPerMm, kPointsPerMm);  // millimetres, y down
      cover(cr, d, whole, title);
      cairo_show_page(cr);
      const double cellW = (kPageW - 2 * kMargin) / kColumns;
      const double cellH = (kPageH - 2 * kMargin) / (kStepsPerPage / kColumns);
      GrowingAssembly pictures(panels, kPictureWidth);
      for (size_t i = 0; i < steps.size(); ++i) {
        const AssemblyStep& step = steps[i];
        const int slot = static_cast<int>(i % kStepsPerPage);
        const double x = kMargin + (slot % kColumns) * cellW, y = kMargin + (slot / kColumns) * cellH;
        double line =
            text(cr, "Step " + std::to_string(i + 1) + ": " + step.id, x, y + 5, 4.5, cellW - 4, true);
        std::string how;
        if (i == 0) how = "Hold it upright; the next patches slide onto it.";
        if (!step.fromTop.empty()) how += "Slots opening at the top onto " + joined(step.fromTop) + ". ";
        if (!step.fromBottom.empty())
          how += "Slots opening at the bottom onto " + joined(step.fromBottom) + ". ";
        if (!step.through.empty()) how += "Slots through, onto " + joined(step.through) + ". ";
        if (!step.partnerCuts.empty()) how += "Uncut where " + joined(step.partnerCuts) + " is cut through. ";
        line = text(cr, how, x, line, 3, cellW - 4);
        // The assembly so far on the left, the patch with the slots to engage on the right.
        const int p = step.patch >= 0 ? panelOf[step.patch] : -1;
        const double pictureW = kPictureShare * (cellW - 4), height = y + cellH - line - 3;
        if (p >= 0) drawPicture(cr, pictures.add(p), x, line, pictureW, height);
        const int k = flatIndex[step.patch];
        if (k >= 0) {
          std::vector<std::string> onto = step.fromTop;
          onto.insert(onto.end(), step.fromBottom.begin(), step.fromBottom.end());
          onto.insert(onto.end(), step.through.begin(), step.through.end());
          // As placed on its sheet; a quarter turn more where that draws it kTurnGain times
          // larger: the strip beside the picture is tall and narrow, and a long flat patch
          // came out 30 mm wide with its slot marks run together (ChineseDragon, step 47).
          const double w = cellW - 6 - pictureW, h = height - 4;
          const Placement& placed = d.layout.packing.placements[k];
          FlatView view = flatView(d.layout.patches[k], placed.rotation);
          if (view.scaleIn(w, h, true) > kTurnGain * view.scaleIn(w, h))
            view = flatView(d.layout.patches[k], placed.rotation + 90);
          drawFlatPatch(cr, d.layout.patches[k], view, onto, x + pictureW + 2, line + 2, w, h);
        }
        if (slot == kStepsPerPage - 1 || i + 1 == steps.size()) cairo_show_page(cr);
      }
    });
  });
}

}  // namespace sliceform
