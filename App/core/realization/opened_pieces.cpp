// SPDX-License-Identifier: LGPL-2.1-or-later
#include "realization/opened_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sliceform {
namespace {

struct Segment {
  Vec2 a, b;
};

std::vector<Segment> segments(const std::vector<Region2d::Loop>& loops) {
  std::vector<Segment> out;
  for (const Region2d::Loop& loop : loops)
    for (size_t i = 0, n = loop.size(); i < n; ++i) out.push_back({loop[i], loop[(i + 1) % n]});
  return out;
}

double cross(Vec2 o, Vec2 a, Vec2 b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

double pointSegmentDistance(Vec2 p, const Segment& s) {
  const Vec2 d{s.b.x - s.a.x, s.b.y - s.a.y};
  const double len2 = d.x * d.x + d.y * d.y;
  const double t = len2 > 0 ? std::clamp(((p.x - s.a.x) * d.x + (p.y - s.a.y) * d.y) / len2, 0.0, 1.0) : 0;
  return std::hypot(p.x - s.a.x - t * d.x, p.y - s.a.y - t * d.y);
}

double segmentDistance(const Segment& s, const Segment& t) {
  const double d1 = cross(s.a, s.b, t.a), d2 = cross(s.a, s.b, t.b);
  const double d3 = cross(t.a, t.b, s.a), d4 = cross(t.a, t.b, s.b);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 0;
  return std::min({pointSegmentDistance(s.a, t), pointSegmentDistance(s.b, t), pointSegmentDistance(t.a, s),
                   pointSegmentDistance(t.b, s)});
}

Box2 segmentBox(const Segment& s) {
  return {{std::min(s.a.x, s.b.x), std::min(s.a.y, s.b.y)},
          {std::max(s.a.x, s.b.x), std::max(s.a.y, s.b.y)},
          false};
}

// Whether every edge of one region is more than `gap` mm from every edge of the other (two
// disjoint regions, the components of one region, are then more than `gap` apart). Only
// edges near the other region's box are compared.
bool fartherThan(const std::vector<Segment>& a, const Box2& boxA, const std::vector<Segment>& b,
                 const Box2& boxB, double gap) {
  std::vector<Segment> nearA, nearB;
  for (const Segment& s : a)
    if (!apart(segmentBox(s), boxB, gap)) nearA.push_back(s);
  for (const Segment& s : b)
    if (!apart(segmentBox(s), boxA, gap)) nearB.push_back(s);
  for (const Segment& s : nearA)
    for (const Segment& t : nearB)
      if (!apart(segmentBox(s), segmentBox(t), gap) && !(segmentDistance(s, t) > gap)) return false;
  return true;
}

}  // namespace

// One connected piece of an eroded region: an outer loop with its holes.
struct OpenedPart {
  Region2d region;
  std::vector<Region2d::Loop> loops;  // region.loops()
  double area = 0;                    // mm²
  Box2 box;                           // of the first loop
  // Made once for the pieces ErodedColumns keeps (else when first needed): the edges, and
  // the stretches of boundary along the columns' sides.
  std::vector<Segment> edges;
  std::vector<Region2d::Stretch> stretches;
};

namespace {

// Union-find: the root of i's set in `link` (each one's link to another of its set).
size_t rootOf(std::vector<size_t>& link, size_t i) {
  while (link[i] != i) i = link[i] = link[link[i]];
  return i;
}

OpenedPart makePart(Region2d piece) {
  OpenedPart part;
  part.region = std::move(piece);
  part.loops = part.region.loops();
  part.area = part.region.area();
  for (const Vec2& v : part.loops.front()) {
    if (part.box.empty) part.box = {v, v, false};
    part.box.min = {std::min(part.box.min.x, v.x), std::min(part.box.min.y, v.y)};
    part.box.max = {std::max(part.box.max.x, v.x), std::max(part.box.max.y, v.y)};
  }
  return part;
}

// A piece ErodedColumns keeps for many counts, its edges and its stretches along the
// columns' sides (`sides`, sorted) made once.
OpenedPart keptPart(Region2d piece, const std::vector<double>& sides) {
  OpenedPart part = makePart(std::move(piece));
  part.edges = segments(part.loops);
  part.stretches = part.region.stretchesOn(sides);
  return part;
}

std::vector<OpenedPart> keptParts(std::vector<Region2d> pieces, const std::vector<double>& sides) {
  std::vector<OpenedPart> out;
  for (Region2d& piece : pieces) out.push_back(keptPart(std::move(piece), sides));
  return out;
}

// Growing the eroded region back (round corners at every vertex, then a union) was most
// of the search's time, and it is seldom needed. Each eroded part grows into one connected
// piece, and two parts' growths (by neck) meet exactly when the parts come within 2 neck
// of each other. So the opened region's pieces are the clusters of parts linked by that
// distance (plus a margin for rounding to Clipper units: a bridge within a micron of the
// neck may count either way), found without growing anything. Only a cluster small enough
// to be a crumb, or a sliver, is grown back, to measure it. (Growing the whole region back
// whenever two parts came close cost every move on a patch with a natural neck, such as
// the Menger sponge's, two offsets of the whole patch.) Opened pieces smaller than `small`
// go to `smallPieces` when it is given. `cluster`: parts known to be linked already, as
// each part's link to another of its cluster (ErodedColumns' pieces of one piece of
// paper), or empty.
int countOpenedParts(const std::vector<const OpenedPart*>& parts, double neck, double crumb, double small,
                     std::vector<Region2d>* smallPieces, std::vector<size_t> cluster = {}) {
  const double gap = 2 * neck + 1e-3;
  if (cluster.empty()) {
    cluster.resize(parts.size());
    std::iota(cluster.begin(), cluster.end(), size_t{0});
  }
  const auto root = [&](size_t i) { return rootOf(cluster, i); };
  std::vector<std::vector<Segment>> made(parts.size());
  const auto edges = [&](size_t k) -> const std::vector<Segment>& {
    if (!parts[k]->edges.empty()) return parts[k]->edges;
    if (made[k].empty()) made[k] = segments(parts[k]->loops);
    return made[k];
  };
  // The clusters given, each with its box: two are linked where a part of one comes within
  // the gap of a part of the other.
  std::vector<std::vector<size_t>> given(parts.size());
  std::vector<Box2> boxes(parts.size());
  for (size_t i = 0; i < parts.size(); ++i) {
    const size_t r = root(i);
    given[r].push_back(i);
    const Box2& b = parts[i]->box;
    Box2& box = boxes[r];
    box = box.empty ? b
                    : Box2{{std::min(box.min.x, b.min.x), std::min(box.min.y, b.min.y)},
                           {std::max(box.max.x, b.max.x), std::max(box.max.y, b.max.y)},
                           false};
  }
  std::vector<size_t> heads;
  for (size_t i = 0; i < parts.size(); ++i)
    if (!given[i].empty()) heads.push_back(i);
  const auto linked = [&](size_t a, size_t b) {
    for (const size_t i : given[a])
      for (const size_t j : given[b])
        if (!apart(parts[i]->box, parts[j]->box, gap) &&
            !fartherThan(edges(i), parts[i]->box, edges(j), parts[j]->box, gap))
          return true;
    return false;
  };
  for (size_t x = 0; x < heads.size(); ++x)
    for (size_t y = x + 1; y < heads.size(); ++y) {
      const size_t a = heads[x], b = heads[y];
      if (root(a) == root(b) || apart(boxes[a], boxes[b], gap)) continue;
      if (linked(a, b)) cluster[root(b)] = root(a);
    }
  std::vector<std::vector<size_t>> members(parts.size());
  for (size_t i = 0; i < parts.size(); ++i) members[root(i)].push_back(i);
  int n = 0;
  const auto piece = [&](Region2d grown) {
    const double area = grown.area();
    if (area < crumb) return;
    ++n;
    if (smallPieces && area < small) smallPieces->push_back(std::move(grown));
  };
  for (const std::vector<size_t>& group : members) {
    if (group.empty()) continue;
    double area = 0;
    for (const size_t i : group) area += parts[i]->area;
    // Clear of crumb-sized and small pieces by far: counted without growing (else grown
    // back and normalised as components() would, so a piece near the crumb size is
    // measured as before).
    if (area >= std::max(2 * crumb, small)) {
      ++n;
      continue;
    }
    std::vector<Region2d> together;
    for (const size_t i : group) together.push_back(parts[i]->region);
    Region2d grown = Region2d::uniteAtOnce(together).offset(neck);
    piece(std::move(grown));
  }
  return n;
}

int countPieces(std::vector<Region2d> pieces, double neck, double crumb, double small,
                std::vector<Region2d>* smallPieces) {
  std::vector<OpenedPart> parts;
  for (Region2d& piece : pieces) parts.push_back(makePart(std::move(piece)));
  std::vector<const OpenedPart*> all;
  for (const OpenedPart& part : parts) all.push_back(&part);
  return countOpenedParts(all, neck, crumb, small, smallPieces);
}

// Pieces that share a stretch of a column's side are one piece of paper: each one's link
// to another of its piece, as countOpenedParts takes them. Two pieces on one side of a line
// never share a stretch of it (they would overlap), so a shared stretch joins pieces from
// either side. A stretch shared over a point only is left to the neck test, which links
// the two anyway.
std::vector<size_t> joinedAlongSides(const std::vector<const OpenedPart*>& parts) {
  struct At {
    Region2d::Stretch s;
    size_t part;
  };
  std::vector<At> all;
  for (size_t k = 0; k < parts.size(); ++k)
    for (const Region2d::Stretch& s : parts[k]->stretches) all.push_back({s, k});
  std::sort(all.begin(), all.end(),
            [](const At& a, const At& b) { return a.s.x != b.s.x ? a.s.x < b.s.x : a.s.y.lo < b.s.y.lo; });
  std::vector<size_t> link(parts.size());
  std::iota(link.begin(), link.end(), size_t{0});
  const auto root = [&](size_t i) { return rootOf(link, i); };
  for (size_t i = 0; i < all.size(); ++i)
    for (size_t j = i + 1; j < all.size() && all[j].s.x == all[i].s.x && all[j].s.y.lo < all[i].s.y.hi; ++j)
      if (root(all[i].part) != root(all[j].part)) link[root(all[j].part)] = root(all[i].part);
  return link;
}

// On Region2d's grid: a column's sides are where its Booleans put them.
double snapped(double mm) {
  return std::round(mm * Region2d::kUnitsPerMm) / Region2d::kUnitsPerMm;
}

// mm a column is widened by on each side beyond its slots: a slot's grown strip on the
// same line may come out a unit wider by rounding, and would make the columns again.
constexpr double kColumnPad = 1e-3;
// The columns' paper less slots, kept: a patch's searches try a few choices per column.
constexpr size_t kMaxKept = 4096;

}  // namespace

int openedPiecesOfEroded(const Region2d& eroded, double neck, double crumb, double small,
                         std::vector<Region2d>* smallPieces) {
  return countPieces(eroded.components(), neck, crumb, small, smallPieces);
}

int openedPieceCount(const Region2d& region, double neck, double crumb) {
  return openedPiecesOfEroded(region.offset(-neck), neck, crumb);
}

int openedPieceCountFull(const Region2d& region, double neck, double crumb) {
  int n = 0;
  for (const Region2d& piece : region.offset(-neck).offset(neck).components())
    n += piece.area() >= crumb ? 1 : 0;
  return n;
}

int openedPiecesLess(const Region2d& eroded, const Region2d& grown, double neck, double crumb, double small,
                     std::vector<Region2d>* smallPieces) {
  return countPieces(eroded.subtractComponentsRaw(grown), neck, crumb, small, smallPieces);
}

// The columns (x ranges in mm on Region2d's grid, sorted, apart), their sides, the paper
// between them, and each one's paper.
struct ErodedColumns::Layout {
  std::vector<Range> columns;
  std::vector<double> sides;
  std::vector<OpenedPart> between;
  std::vector<std::vector<OpenedPart>> within;
  std::vector<Region2d> paper;  // within[k] overlaid

  // The column holding [lo, hi], or columns.size().
  size_t holding(double lo, double hi) const {
    auto it = std::upper_bound(columns.begin(), columns.end(), lo,
                               [](double x, const Range& c) { return x < c.first; });
    if (it == columns.begin()) return columns.size();
    --it;
    return hi <= it->second ? static_cast<size_t>(it - columns.begin()) : columns.size();
  }
};

ErodedColumns::ErodedColumns(const Region2d& eroded, double neck, double crumb, double widest, double reach,
                             const std::vector<double>& lines, double halfWidth)
    : eroded_(&eroded), neck_(neck), crumb_(crumb), widest_(widest), reach_(reach + 1e-5) {
  for (const double x : lines) expected_.emplace_back(x - halfWidth - reach_, x + halfWidth + reach_);
}

ErodedColumns::~ErodedColumns() = default;

std::shared_ptr<const ErodedColumns::Layout> ErodedColumns::layoutFor(
    const std::vector<Range>& ranges) const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (layout_ && std::all_of(ranges.begin(), ranges.end(), [&](const Range& r) {
        return layout_->holding(r.first, r.second) < layout_->columns.size();
      }))
    return layout_;
  // The columns so far and the new ranges, widened, those that touch merged.
  std::vector<Range> all = layout_ ? layout_->columns : std::vector<Range>{};
  if (!layout_)
    for (const Range& r : expected_)
      all.emplace_back(snapped(r.first - kColumnPad), snapped(r.second + kColumnPad));
  for (const Range& r : ranges)
    all.emplace_back(snapped(r.first - kColumnPad), snapped(r.second + kColumnPad));
  std::sort(all.begin(), all.end());
  auto next = std::make_shared<Layout>();
  for (const Range& r : all)
    if (!next->columns.empty() && r.first <= next->columns.back().second)
      next->columns.back().second = std::max(next->columns.back().second, r.second);
    else
      next->columns.push_back(r);
  for (const Range& c : next->columns) next->sides.insert(next->sides.end(), {c.first, c.second});
  // The patch cut along the columns' sides: two differences, each turned as the slot tests'
  // (Region2d::subtractComponentsRaw), so that both meet each side at the same points.
  const Box2 box = eroded_->bounds();
  const double y0 = box.min.y - 1, y1 = box.max.y + 1;
  const double x0 = snapped(box.min.x - 1), x1 = snapped(box.max.x + 1);
  std::vector<Region2d::Loop> columns, gaps;
  double from = x0;
  for (const Range& c : next->columns) {
    columns.push_back(Region2d::rectangle(c.first, y0, c.second, y1));
    if (c.first > from) gaps.push_back(Region2d::rectangle(from, y0, c.first, y1));
    from = std::max(from, c.second);
  }
  if (x1 > from) gaps.push_back(Region2d::rectangle(from, y0, x1, y1));
  next->between = keptParts(eroded_->subtractComponentsRaw(Region2d::overlaidLoops(columns)), next->sides);
  next->within.resize(next->columns.size());
  for (OpenedPart& part :
       keptParts(eroded_->subtractComponentsRaw(Region2d::overlaidLoops(gaps)), next->sides)) {
    const double middle = (part.box.min.x + part.box.max.x) / 2;
    const size_t c = next->holding(middle, middle);
    (c < next->columns.size() ? next->within[c] : next->between).push_back(std::move(part));
  }
  for (const std::vector<OpenedPart>& parts : next->within) {
    std::vector<Region2d> regions;
    for (const OpenedPart& part : parts) regions.push_back(part.region);
    next->paper.push_back(Region2d::overlaid(regions));
  }
  layout_ = next;
  return layout_;
}

std::shared_ptr<const ErodedColumns::Parts> ErodedColumns::columnLess(
    const Layout& layout, size_t column, const std::vector<Region2d::Loop>& slots, const Grow& grow) const {
  const auto [lo, hi] = layout.columns[column];
  std::vector<double> key = {lo, hi};
  for (const Region2d::Loop& loop : slots) {
    key.push_back(static_cast<double>(loop.size()));
    for (const Vec2& p : loop) key.insert(key.end(), {p.x, p.y});
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = columns_.find(key);
    if (it != columns_.end()) return it->second;
  }
  const std::vector<Region2d> grown = grow(Region2d::overlaidLoops(slots));
  for (const Region2d& g : grown) {
    const Box2 b = g.bounds();
    if (!b.empty && (b.min.x < lo || b.max.x > hi)) return nullptr;
  }
  auto parts = std::make_shared<const Parts>(
      keptParts(layout.paper[column].subtractComponentsRaw(Region2d::overlaid(grown)), layout.sides));
  std::lock_guard<std::mutex> lock(mutex_);
  if (columns_.size() >= kMaxKept) columns_.clear();
  columns_.emplace(std::move(key), parts);
  return parts;
}

std::optional<int> ErodedColumns::less(const Region2d& slots, const Grow& grow, double small,
                                       std::vector<Region2d>* smallPieces) const {
  if (slots.holeCount() > 0) return std::nullopt;
  const std::vector<Region2d::Loop> loops = slots.loops();
  std::vector<Range> ranges;
  for (const Region2d::Loop& loop : loops) {
    double lo = loop.front().x, hi = lo;
    for (const Vec2& p : loop) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
    if (hi - lo + 2 * neck_ > widest_) return std::nullopt;
    ranges.emplace_back(lo - reach_, hi + reach_);
  }
  if (eroded_->empty()) return 0;
  const std::shared_ptr<const Layout> layout = layoutFor(ranges);
  std::vector<std::vector<Region2d::Loop>> inColumn(layout->columns.size());
  for (size_t k = 0; k < ranges.size(); ++k)
    inColumn[layout->holding(ranges[k].first, ranges[k].second)].push_back(loops[k]);
  std::vector<const OpenedPart*> parts;
  for (const OpenedPart& part : layout->between) parts.push_back(&part);
  std::vector<std::shared_ptr<const Parts>> cut;
  for (size_t c = 0; c < inColumn.size(); ++c) {
    const Parts* paper = &layout->within[c];
    if (!inColumn[c].empty()) {
      cut.push_back(columnLess(*layout, c, inColumn[c], grow));
      if (!cut.back()) return std::nullopt;
      paper = cut.back().get();
    }
    for (const OpenedPart& part : *paper) parts.push_back(&part);
  }
  return countOpenedParts(parts, neck_, crumb_, small, smallPieces, joinedAlongSides(parts));
}

}  // namespace sliceform
