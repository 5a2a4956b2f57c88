// SPDX-License-Identifier: LGPL-2.1-or-later
#include "layout/nesting.hpp"

#include <libnest2d/libnest2d.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <regex>

#include "geometry/simplify.hpp"
#include "layout/first_fit.hpp"
#include "support/error.hpp"

namespace sliceform {
namespace {

// libnest2d works in Clipper integers; a micrometre is far finer than any cutter.
constexpr double kUnits = 1000;

ClipperLib::cInt units(double mm) {
  return static_cast<ClipperLib::cInt>(std::llround(mm * kUnits));
}

// The convex hull of the paper, in millimetres.
Region2d::Loop hullOf(const Region2d& outline) {
  ClipperLib::Path points;
  for (const Region2d::Loop& loop : outline.loops())
    if (Region2d::signedArea(loop) > 0)
      for (const Vec2& p : loop) points.push_back({units(p.x), units(p.y)});
  // Closed, as libnest2d's hull takes it: open, a triangle's three points read as two.
  if (!points.empty()) points.push_back(points.front());
  Region2d::Loop hull;
  for (const ClipperLib::IntPoint& p : libnest2d::shapelike::convexHull(points))
    hull.push_back({p.X / kUnits, p.Y / kUnits});
  if (hull.size() > 1 && hull.front().x == hull.back().x && hull.front().y == hull.back().y) hull.pop_back();
  return hull;
}

// How far a patch's nesting contour may stand off its hull, mm: the hull of a curved patch
// drawn within kOutlineDeflection has a vertex every few degrees (25-70 a patch on bear.off
// and knot2.off), and libnest2d's no-fit polygons and their unions cost time with them.
// Grown by this much and simplified within it, the contour holds the hull with 40-60 % of
// its vertices (bear.off: 4995 -> 1965 in all; nesting 905 -> 666 ms, the same 4 sheets);
// parts end up at most this much further apart than the spacing asks.
constexpr double kContourSlack = 0.3;

// What libnest2d nests for a patch: a convex polygon around its paper, as one clockwise,
// closed contour. Decision (docs/decisions.md): libnest2d 5.0 computes no-fit polygons for
// convex shapes only; given a non-convex one it places parts over each other (an L-shape
// test put them 23 mm apart where they are 60 mm wide). Hulls are always correct; what they
// waste inside concave patches is the price.
// The hull is grown by kContourSlack (round corners as chords at most a third of it inside
// the arcs), then simplified within what is left: Douglas-Peucker leaves out only points
// within that distance of the chord that replaces them, so the contour still holds the hull.
// `quarter`: turned a quarter turn counter-clockwise about the origin first.
ClipperLib::Path nestingContour(const Region2d& outline, bool quarter) {
  const Region2d::Loop hull = hullOf(outline);
  if (hull.size() < 3) throw Error(ErrorKind::Geometry, "a flattened patch has no area to nest");
  const double chord = kContourSlack / 3;
  const Region2d grown = Region2d::fromLoops({hull}).coarseOffset(kContourSlack, chord);
  const Region2d coarse = simplified(grown, kContourSlack - chord - 1 / kUnits);
  ClipperLib::Path points;
  for (const Region2d::Loop& loop : coarse.loops())
    for (const Vec2& p : loop)
      points.push_back(quarter ? ClipperLib::IntPoint{units(-p.y), units(p.x)}
                               : ClipperLib::IntPoint{units(p.x), units(p.y)});
  ClipperLib::Path path = libnest2d::shapelike::convexHull(points);
  if (!path.empty() && path.front() == path.back()) path.pop_back();
  if (path.size() < 3) throw Error(ErrorKind::Geometry, "a flattened patch has no area to nest");
  if (ClipperLib::Orientation(path)) ClipperLib::ReversePath(path);
  path.push_back(path.front());
  return path;
}

double paperArea(const std::vector<Region2d>& outlines) {
  double area = 0;
  for (const Region2d& r : outlines) area += r.area();
  return area;
}

// Whether the patch fits the sheet only turned a quarter turn; throws when it fits no way.
bool fitsOnlyTurned(const Box2& b, const std::string& name, const SheetSpec& s) {
  const double w = b.max.x - b.min.x, h = b.max.y - b.min.y;
  const double W = s.width - 2 * s.margin, H = s.height - 2 * s.margin;
  const bool upright = w <= W && h <= H, turned = s.rotate && h <= W && w <= H;
  if (!upright && !turned) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "patch %s is %.1f x %.1f mm and does not fit a %s sheet (%.0f x %.0f mm inside %.0f mm "
                  "margins): choose a larger --sheet or a smaller --size",
                  name.c_str(), w, h, s.name.c_str(), W, H, s.margin);
    throw Error(ErrorKind::BadParameter, text);
  }
  return !upright;
}

// Round-off the room test allows for, in libnest2d's units (10 µm): a part that fits
// exactly is not ruled out.
constexpr double kRoomSlack = 10;

// The convex `loop` (libnest2d's units) shrunk toward its vertices' mean so that every edge
// moves in by kRoomSlack at least, in mm.
Region2d::Loop shrunk(const ClipperLib::Path& loop) {
  double cx = 0, cy = 0;
  for (const ClipperLib::IntPoint& p : loop)
    cx += static_cast<double>(p.X) / loop.size(), cy += static_cast<double>(p.Y) / loop.size();
  double near = HUGE_VAL;
  for (size_t i = 0; i < loop.size(); ++i) {
    const ClipperLib::IntPoint a = loop[i], b = loop[(i + 1) % loop.size()];
    const double dx = static_cast<double>(b.X - a.X), dy = static_cast<double>(b.Y - a.Y),
                 l = std::hypot(dx, dy);
    if (l > 0) near = std::min(near, std::abs(dx * (cy - a.Y) - dy * (cx - a.X)) / l);
  }
  if (!(near > kRoomSlack)) return {};
  const double f = 1 - kRoomSlack / near;
  Region2d::Loop out;
  for (const ClipperLib::IntPoint& p : loop)
    out.push_back({(cx + f * (p.X - cx)) / kUnits, (cy + f * (p.Y - cy)) / kUnits});
  return out;
}

// The convex loop counter-clockwise from its lowest vertex (leftmost of the lowest), without
// a closing repeat.
ClipperLib::Path fromLowest(ClipperLib::Path loop) {
  if (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
  if (!ClipperLib::Orientation(loop)) std::reverse(loop.begin(), loop.end());
  const auto lowest = std::min_element(loop.begin(), loop.end(), [](const auto& a, const auto& b) {
    return a.Y < b.Y || (a.Y == b.Y && a.X < b.X);
  });
  std::rotate(loop.begin(), lowest, loop.end());
  return loop;
}

// The Minkowski sum of two convex loops: their edges merged in the order they turn.
ClipperLib::Path convexSum(const ClipperLib::Path& first, const ClipperLib::Path& second) {
  const ClipperLib::Path a = fromLowest(first), b = fromLowest(second);
  const size_t n = a.size(), m = b.size();
  ClipperLib::Path out;
  out.reserve(n + m);
  for (size_t i = 0, j = 0; i < n || j < m;) {
    out.push_back({a[i % n].X + b[j % m].X, a[i % n].Y + b[j % m].Y});
    const ClipperLib::IntPoint ea{a[(i + 1) % n].X - a[i % n].X, a[(i + 1) % n].Y - a[i % n].Y};
    const ClipperLib::IntPoint eb{b[(j + 1) % m].X - b[j % m].X, b[(j + 1) % m].Y - b[j % m].Y};
    const double turn = static_cast<double>(ea.X) * eb.Y - static_cast<double>(ea.Y) * eb.X;
    if (j == m || (i < n && turn > 0))
      ++i;
    else if (i == n || turn < 0)
      ++j;
    else
      ++i, ++j;
  }
  return out;
}

// Whether `part`, turned a quarter turn `turns` times in all (1: as it is, 4: every way),
// may have room on a sheet holding `placed`: libnest2d takes a place where the part
// overlaps none of them and the box around all of them fits the sheet (it moves them
// together onto the sheet after). All are convex, so the translations that put the part
// over a placed one are the inside of the sum of that one and the part mirrored (their
// no-fit polygon). Where the translations the box allows all lie in those, it has none.
bool roomFor(const libnest2d::Box& bin, const FirstFitSkipping<libnest2d::PolygonImpl>::ItemGroup& placed,
             const libnest2d::Item& part, int turns) {
  ClipperLib::cInt px0 = std::numeric_limits<ClipperLib::cInt>::max(), py0 = px0, px1 = -px0, py1 = -px0;
  for (const auto& item : placed)
    for (const ClipperLib::IntPoint& p : item.get().transformedShape().Contour)
      px0 = std::min(px0, p.X), px1 = std::max(px1, p.X), py0 = std::min(py0, p.Y), py1 = std::max(py1, p.Y);
  const double W = static_cast<double>(bin.width()), H = static_cast<double>(bin.height());
  ClipperLib::Path shape = part.transformedShape().Contour;
  if (shape.size() > 1 && shape.front() == shape.back()) shape.pop_back();
  for (int turn = 0; turn < turns; ++turn) {
    if (turn > 0)
      for (ClipperLib::IntPoint& p : shape) p = {-p.Y, p.X};
    ClipperLib::cInt x0 = shape.front().X, x1 = x0, y0 = shape.front().Y, y1 = y0;
    for (const ClipperLib::IntPoint& p : shape)
      x0 = std::min(x0, p.X), x1 = std::max(x1, p.X), y0 = std::min(y0, p.Y), y1 = std::max(y1, p.Y);
    const double lx = px1 - W - x0 - kRoomSlack, hx = px0 + W - x1 + kRoomSlack;
    const double ly = py1 - H - y0 - kRoomSlack, hy = py0 + H - y1 + kRoomSlack;
    if (lx > hx || ly > hy) continue;
    ClipperLib::Path negated;
    for (const ClipperLib::IntPoint& p : shape) negated.push_back({-p.X, -p.Y});
    std::vector<Region2d::Loop> over;
    for (const auto& item : placed) {
      if (Region2d::Loop loop = shrunk(convexSum(item.get().transformedShape().Contour, negated));
          loop.size() >= 3)
        over.push_back(std::move(loop));
    }
    const Region2d box = Region2d::fromLoops({{{lx / kUnits, ly / kUnits},
                                               {hx / kUnits, ly / kUnits},
                                               {hx / kUnits, hy / kUnits},
                                               {lx / kUnits, hy / kUnits}}});
    if (!box.subtract(Region2d::fromLoops(over, FillRule::NonZero)).empty()) return true;
  }
  return false;
}

// libnest2d's nesting of `items` on sheets `bin` (spacing, turns and placer as `sheet` and
// the comments say), with the selection `Selection` configured by `selection`; the sheets used.
template <class Selection>
size_t nestWith(std::vector<libnest2d::Item>& items, const libnest2d::Box& bin, const SheetSpec& sheet,
                const typename Selection::Config& selection) {
  using namespace libnest2d;
  NestConfig<NfpPlacer, Selection> config;
  // Quarter turns, in order: roomFor turns the part as these do.
  config.placer_config.rotations = {0.0};
  if (sheet.rotate) config.placer_config.rotations = {0.0, Pi / 2, Pi, 3 * Pi / 2};
  config.placer_config.alignment = NfpPlacer::Config::Alignment::BOTTOM_LEFT;
  config.placer_config.starting_point = NfpPlacer::Config::Alignment::BOTTOM_LEFT;
  // One thread: the result must not depend on which thread finishes first.
  config.placer_config.parallel = false;
  // Fewer candidate positions per item than libnest2d's 0.65: the same sheet counts on
  // spot, rocker-arm, bunny-lowres and fandisk, in 60-90 % of the time.
  config.placer_config.accuracy = 0.3f;
  config.selector_config = selection;
  return nest(items, bin, units(sheet.spacing), config);
}

}  // namespace

SheetSpec sheetSpec(const std::string& name, double margin, double spacing) {
  SheetSpec s;
  s.name = name;
  s.margin = margin;
  s.spacing = spacing;
  std::smatch m;
  if (name == "A4") {
    s.width = 210, s.height = 297;
  } else if (name == "A3") {
    s.width = 297, s.height = 420;
  } else if (name == "Letter") {
    s.width = 215.9, s.height = 279.4;
  } else if (std::regex_match(name, m, std::regex(R"(([0-9.]+)x([0-9.]+))"))) {
    s.width = std::stod(m[1]), s.height = std::stod(m[2]);
  } else {
    throw Error(ErrorKind::BadParameter, "unknown sheet '" + name + "': use A4, A3, Letter or WxH in mm");
  }
  if (!(margin >= 0) || !(spacing >= 0))
    throw Error(ErrorKind::BadParameter, "the sheet margin and spacing must not be negative");
  if (!(s.width > 2 * margin && s.height > 2 * margin))
    throw Error(ErrorKind::BadParameter, "the sheet " + name + " leaves no room inside its margins");
  return s;
}

Vec2 Placement::apply(Vec2 p) const {
  const double r = rotation * M_PI / 180, c = std::cos(r), s = std::sin(r);
  return {c * p.x - s * p.y + offset.x, s * p.x + c * p.y + offset.y};
}

Packing nestOnSheets(const std::vector<Region2d>& outlines, const std::vector<std::string>& names,
                     const SheetSpec& sheet, bool askEverySheet) {
  using namespace libnest2d;
  // A patch that fits only turned is handed over turned: libnest2d tries its rotations
  // against the sheets it has, but sets an item that fits none of them on a new sheet as it
  // comes, and gives up (a 300 x 200 mm patch on A3, whose 277 x 400 mm fit it turned).
  std::vector<Item> items;
  std::vector<bool> turned(outlines.size());
  for (size_t i = 0; i < outlines.size(); ++i) {
    turned[i] = fitsOnlyTurned(outlines[i].bounds(), names[i], sheet);
    items.emplace_back(nestingContour(outlines[i], turned[i]), ClipperLib::Paths{});
  }
  // libnest2d grows every item by half the spacing, the bin too: widen the bin by as much
  // so the paper keeps exactly `margin` from the sheet's edges.
  const double edge = sheet.margin - sheet.spacing / 2;
  const Box bin({units(edge), units(edge)}, {units(sheet.width - edge), units(sheet.height - edge)});
  const size_t bins = askEverySheet ? nestWith<FirstFitSelection>(items, bin, sheet, {})
                                    : nestWith<FirstFitSkipping<PolygonImpl>>(
                                          items, bin, sheet, [&](const auto& placed, const Item& part) {
                                            return roomFor(bin, placed, part, sheet.rotate ? 4 : 1);
                                          });

  Packing packing;
  packing.sheets = static_cast<int>(bins);
  for (size_t i = 0; i < items.size(); ++i) {
    const Item& item = items[i];
    if (item.binId() < 0) throw Error(ErrorKind::Geometry, "libnest2d left a patch off every sheet");
    const auto t = item.translation();
    const double degrees = std::round(static_cast<double>(item.rotation()) * 180 / Pi) + (turned[i] ? 90 : 0);
    packing.placements.push_back({item.binId(), {t.X / kUnits, t.Y / kUnits}, std::fmod(degrees + 360, 360)});
  }
  packing.utilisation = paperArea(outlines) / (packing.sheets * sheet.width * sheet.height);
  return packing;
}

Packing shelfPack(const std::vector<Region2d>& outlines, const std::vector<std::string>& names,
                  const SheetSpec& sheet) {
  // Left to right in rows from the top, as in the paper's figures; a new row when the
  // sheet is full across, a new sheet when it is full down. Upright, but for a patch that
  // fits the sheet only turned a quarter turn.
  Packing packing;
  packing.sheets = outlines.empty() ? 0 : 1;
  double x = sheet.margin, top = sheet.height - sheet.margin, rowHeight = 0;
  for (size_t i = 0; i < outlines.size(); ++i) {
    Box2 b = outlines[i].bounds();
    const bool turned = fitsOnlyTurned(b, names[i], sheet);
    if (turned) b = {{-b.max.y, b.min.x}, {-b.min.y, b.max.x}, false};  // (x, y) -> (-y, x)
    const double w = b.max.x - b.min.x, h = b.max.y - b.min.y;
    if (x + w > sheet.width - sheet.margin) x = sheet.margin, top -= rowHeight + sheet.spacing, rowHeight = 0;
    if (top - h < sheet.margin)
      ++packing.sheets, x = sheet.margin, top = sheet.height - sheet.margin, rowHeight = 0;
    packing.placements.push_back({packing.sheets - 1, {x - b.min.x, top - h - b.min.y}, turned ? 90.0 : 0.0});
    x += w + sheet.spacing;
    rowHeight = std::max(rowHeight, h);
  }
  packing.utilisation =
      packing.sheets ? paperArea(outlines) / (packing.sheets * sheet.width * sheet.height) : 0;
  return packing;
}

}  // namespace sliceform
