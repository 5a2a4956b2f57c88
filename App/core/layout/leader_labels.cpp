// SPDX-License-Identifier: LGPL-2.1-or-later
// The last resort for a partner label: where no label beside a slot or on its line reads
// as that slot's (the slot is at a tip narrower than a 1 mm label with its margins, or its
// line runs along the outline), the label stands off in the nearest room and an engraved
// leader joins it to the slot, as a drawing's note points at what it names. The leader is
// the shortest path over the paper, bending where the paper turns (round a slot's root,
// out of a narrow tip), that crosses no label and no other leader.
#include <algorithm>
#include <cmath>
#include <optional>

#include "layout/label_room.hpp"

namespace sliceform {
namespace {

constexpr double kReach = 15;       // mm from the slot the label may stand
constexpr double kMaxLeader = 25;   // mm: a longer leader is a path to follow, not a pointer
constexpr double kStandOff = 0.25;  // mm between a leader's end and the text it leads to
constexpr double kStep = 0.5;       // mm between the centres tried
constexpr double kInset = 0.05;     // mm a bend keeps inside the leader's paper
// mm between a leader and another label: the labels' own gap where the paper allows, so a
// leader does not read as underlining a label it passes; where it does not, less.
constexpr double kLeaderGaps[] = {kGap, 0.2};
constexpr size_t kCentres = 64;  // centres a size tries, nearest the slot first

struct Segment {
  Vec2 a, b;
};

double cross(Vec2 o, Vec2 a, Vec2 b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Not std::hypot: glibc's guards against overflow and rounds correctly, at several times
// the cost, and the paths and centres ask it of every pair (MODERN_Cooker_1: 16 % of the
// leaders' time). Lengths here are millimetres on a sheet.
double distance(Vec2 a, Vec2 b) {
  const double dx = a.x - b.x, dy = a.y - b.y;
  return std::sqrt(dx * dx + dy * dy);
}

bool segmentsCross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  return cross(a, b, c) * cross(a, b, d) < 0 && cross(c, d, a) * cross(c, d, b) < 0;
}

// Whether the segment a-b meets the box [lo, hi] (Liang-Barsky clipping).
bool meetsBox(Vec2 a, Vec2 b, Vec2 lo, Vec2 hi) {
  double t0 = 0, t1 = 1;
  const double d[2] = {b.x - a.x, b.y - a.y}, p[2] = {a.x, a.y}, l[2] = {lo.x, lo.y}, h[2] = {hi.x, hi.y};
  for (int k = 0; k < 2; ++k) {
    if (std::abs(d[k]) < 1e-12) {
      if (p[k] < l[k] || p[k] > h[k]) return false;
      continue;
    }
    double e0 = (l[k] - p[k]) / d[k], e1 = (h[k] - p[k]) / d[k];
    if (e0 > e1) std::swap(e0, e1);
    t0 = std::max(t0, e0), t1 = std::min(t1, e1);
    if (t0 > t1) return false;
  }
  return true;
}

// Whether the segment a-b lies over `room` all along, to Clipper's units: the final word
// on a leader the quicker tests below chose. A speck of rounding at an end is no exit.
bool overPaper(const Region2d& room, Vec2 a, Vec2 b) {
  return room.containsSegment(a, b, 1e-3);
}

// Where a leader may end at the slot, in its paper: just beyond either end of the slot on
// its line (the end at the outline is off the paper, the root is not), or beside its
// middle (a slot cut right through its hinge has no root).
std::vector<Vec2> targets(const Region2d& room, const LabelSpot& s) {
  const double d = kLeaderMargin + kInset, mid = (s.slot.lo + s.slot.hi) / 2;
  std::vector<Vec2> ends;
  if (s.slot.hi - s.slot.lo < 1e-9)
    ends = {{s.x, s.slot.lo}};
  else
    ends = {{s.x, s.slot.lo - d},
            {s.x, s.slot.hi + d},
            {s.x + s.slotWidth / 2 + d, mid},
            {s.x - s.slotWidth / 2 - d, mid}};
  std::vector<Vec2> in;
  for (const Vec2& t : ends)
    if (room.contains(t)) in.push_back(t);
  return in;
}

// The paper a leader crosses near one slot: the leader paper's edges within reach, the
// points where a shortest path may bend (its reflex corners, a little inside), and what a
// leader must not cross (the labels' boxes grown by the gap, and the leaders drawn).
struct Field {
  const Region2d& room;
  mutable std::vector<Segment> edges;  // clear() moves the last to block to the front
  std::vector<Segment> leaders;
  std::vector<Vec2> bends;
  std::vector<std::pair<Vec2, Vec2>> boxes;

  Field(const Region2d& leaderRoom, const std::vector<Label>& taken, Vec2 t, double g) : room(leaderRoom) {
    const double r = kReach + kMaxLeader / 2;
    const auto near = [&](Vec2 p) { return std::abs(p.x - t.x) < r && std::abs(p.y - t.y) < r; };
    for (const Region2d::Loop& loop : room.loops())
      for (size_t i = 0, n = loop.size(); i < n; ++i) {
        const Vec2 a = loop[(i + n - 1) % n], v = loop[i], b = loop[(i + 1) % n];
        if (near(v) || near(b)) edges.push_back({v, b});
        // The paper lies left of every loop (outer loops counter-clockwise, holes
        // clockwise): a right turn is a corner a path bends round, just inside it.
        if (!near(v) || cross(a, v, b) >= 0) continue;
        const double la = distance(a, v), lb = distance(v, b);
        if (la < 1e-9 || lb < 1e-9) continue;
        const Vec2 na{-(v.y - a.y) / la, (v.x - a.x) / la}, nb{-(b.y - v.y) / lb, (b.x - v.x) / lb};
        const double nl = std::hypot(na.x + nb.x, na.y + nb.y);
        if (nl > 1e-9)
          bends.push_back({v.x + kInset * (na.x + nb.x) / nl, v.y + kInset * (na.y + nb.y) / nl});
      }
    // Every segment tested lies within the square of half side r about t (bends and
    // label centres are in it), so what lies wholly outside it cannot meet one.
    const auto reaches = [&](Vec2 lo, Vec2 hi) {
      return lo.x < t.x + r && hi.x > t.x - r && lo.y < t.y + r && hi.y > t.y - r;
    };
    for (const Label& l : taken) {
      const Vec2 h = halfSize(l.text, l.height, l.vertical);
      const Vec2 lo{l.at.x - h.x - g, l.at.y - h.y - g}, hi{l.at.x + h.x + g, l.at.y + h.y + g};
      if (reaches(lo, hi)) boxes.push_back({lo, hi});
      // A path round a label bends at its box's corners, a little outside.
      const double b = g + kInset;
      for (const Vec2 c :
           {Vec2{l.at.x - h.x - b, l.at.y - h.y - b}, Vec2{l.at.x + h.x + b, l.at.y - h.y - b},
            Vec2{l.at.x + h.x + b, l.at.y + h.y + b}, Vec2{l.at.x - h.x - b, l.at.y + h.y + b}})
        if (near(c) && room.contains(c)) bends.push_back(c);
      for (size_t i = 1; i < l.leader.size(); ++i) {
        const Vec2 a = l.leader[i - 1], b = l.leader[i];
        if (reaches({std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}))
          leaders.push_back({a, b});
      }
    }
  }

  // Whether a leader may run straight from a to b: over the paper, clear of every label
  // and leader.
  bool clear(Vec2 a, Vec2 b) const {
    // The edge that blocked the last leader tried most likely blocks this one (a bend's
    // leaders to the other bends): it is tested first, and kept first (below). The answer
    // is the same in any order (MODERN_Cooker_1: 173 million tests of boxes, leaders and
    // edges -> 62 million).
    if (!edges.empty() && segmentsCross(a, b, edges.front().a, edges.front().b)) return false;
    for (const auto& [lo, hi] : boxes)
      if (meetsBox(a, b, lo, hi)) return false;
    for (const Segment& l : leaders)
      if (segmentsCross(a, b, l.a, l.b)) return false;
    for (size_t i = 1; i < edges.size(); ++i)
      if (segmentsCross(a, b, edges[i].a, edges[i].b)) {
        std::swap(edges[i], edges.front());
        return false;
      }
    return room.contains({(a.x + b.x) / 2, (a.y + b.y) / 2});
  }
};

// Shortest paths from `t` over the field's bends (Dijkstra on the visibility graph):
// `length[i]` and `from[i]` for every bend, and t itself last.
struct Routes {
  std::vector<Vec2> at;
  std::vector<double> length;
  std::vector<int> from;
};

Routes shortestPaths(const Field& f, Vec2 t) {
  Routes p{f.bends, std::vector<double>(f.bends.size() + 1, HUGE_VAL),
           std::vector<int>(f.bends.size() + 1, -1)};
  p.at.push_back(t);
  const size_t n = p.at.size();
  p.length[n - 1] = 0;
  std::vector<bool> done(n, false);
  for (;;) {
    size_t u = n;
    for (size_t i = 0; i < n; ++i)
      if (!done[i] && p.length[i] < kMaxLeader && (u == n || p.length[i] < p.length[u])) u = i;
    if (u == n) break;
    done[u] = true;
    for (size_t v = 0; v < n; ++v) {
      const double l = p.length[u] + distance(p.at[u], p.at[v]);
      if (done[v] || l >= p.length[v] || l >= kMaxLeader || !f.clear(p.at[u], p.at[v])) continue;
      p.length[v] = l, p.from[v] = static_cast<int>(u);
    }
  }
  return p;
}

// The centres a label whose box may have its centre in `room` tries: the point nearest
// `t`, points along the room's edges and a grid over it.
std::vector<Vec2> centres(const Region2d& room, Vec2 t) {
  std::vector<Vec2> out{nearestPoint(room, t)};
  for (const Region2d::Loop& loop : room.loops())
    for (size_t i = 0; i < loop.size(); ++i) {
      const Vec2 a = loop[i], b = loop[(i + 1) % loop.size()];
      const int n = static_cast<int>(distance(a, b) / kStep);
      for (int k = 0; k <= n; ++k)
        out.push_back({a.x + (b.x - a.x) * k / (n + 1), a.y + (b.y - a.y) * k / (n + 1)});
    }
  const Box2 b = room.bounds();
  for (double x = b.min.x + kStep / 2; x < b.max.x; x += kStep)
    for (double y = b.min.y + kStep / 2; y < b.max.y; y += kStep)
      if (room.contains({x, y})) out.push_back({x, y});
  return out;
}

// The shortest leader to a box of half size `half` centred at one of `cs`: from the slot
// along the paths to a point it sees, then straight to the box's edge (less the stand-off).
Stroke shortestLeader(const Field& f, const Routes& p, const std::vector<Vec2>& all, Vec2 half,
                      Vec2& centre) {
  // Only the bends a path reaches count (MODERN_Cooker_1: 2 in 5).
  std::vector<size_t> reached;
  for (size_t u = 0; u < p.at.size(); ++u)
    if (p.length[u] < HUGE_VAL) reached.push_back(u);
  // The centres by how far the paths reach them, not looking where they pass: those behind
  // a cut from the slot come after those round it.
  std::vector<std::pair<double, Vec2>> cs;
  for (const Vec2& c : all) {
    double reach = HUGE_VAL;
    for (const size_t u : reached) reach = std::min(reach, p.length[u] + distance(p.at[u], c));
    if (reach < HUGE_VAL) cs.push_back({reach, c});
  }
  std::stable_sort(cs.begin(), cs.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  if (cs.size() > kCentres) cs.resize(kCentres);
  double best = kMaxLeader;
  Stroke leader;
  for (const auto& [reach, c] : cs) {
    if (reach - half.x - half.y - 2 * kStandOff >= best) break;  // no shorter one beyond
    const Vec2 lo{c.x - half.x - kStandOff, c.y - half.y - kStandOff},
        hi{c.x + half.x + kStandOff, c.y + half.y + kStandOff};
    for (const size_t u : reached) {
      if (p.length[u] >= best) continue;
      const Vec2 end{std::clamp(p.at[u].x, lo.x, hi.x), std::clamp(p.at[u].y, lo.y, hi.y)};
      const double l = p.length[u] + distance(p.at[u], end);
      if (l >= best || !f.clear(p.at[u], end)) continue;
      Stroke path{end};
      for (int v = static_cast<int>(u); v >= 0; v = p.from[v]) path.push_back(p.at[v]);
      std::reverse(path.begin(), path.end());  // from the slot to the label
      // The path to the box must not run over the box itself on its way.
      bool across = false;
      for (size_t i = 1; i + 1 < path.size() && !across; ++i) across = meetsBox(path[i - 1], path[i], lo, hi);
      bool over = !across;
      for (size_t i = 1; i < path.size() && over; ++i) over = overPaper(f.room, path[i - 1], path[i]);
      if (!over) continue;
      best = l, leader = std::move(path), centre = c;
    }
  }
  return leader;
}

// The window every room a leader label of the slot tries lies in: kReach about each of its
// ends `ts` (not empty).
Box2 reachOf(const std::vector<Vec2>& ts) {
  Vec2 lo = ts.front(), hi = ts.front();
  for (const Vec2& t : ts)
    lo = {std::min(lo.x, t.x), std::min(lo.y, t.y)}, hi = {std::max(hi.x, t.x), std::max(hi.y, t.y)};
  return {{lo.x - kReach, lo.y - kReach}, {hi.x + kReach, hi.y + kReach}, false};
}

}  // namespace

std::vector<Box2> leaderBoxes(const std::vector<Label>& labels) {
  std::vector<Box2> boxes;
  for (const Label& l : labels)
    for (size_t i = 1; i < l.leader.size(); ++i) {
      const Vec2 a = l.leader[i - 1], b = l.leader[i];
      boxes.push_back(
          {{std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}, false});
    }
  return boxes;
}

std::vector<Stroke> leaderStrokes(const Stroke& leader) {
  if (leader.size() < 2) return {};
  // An arrowhead at the slot, 0.5 mm long, its barbs 20 degrees off the leader: it stays
  // within 0.2 mm of the leader's line, on the paper the leader crosses.
  const Vec2 a = leader[0], b = leader[1];
  const double l = distance(a, b), len = std::min(0.5, l), c = std::cos(0.35), s = std::sin(0.35);
  const Vec2 d{(b.x - a.x) / l * len, (b.y - a.y) / l * len};
  const Vec2 left{a.x + c * d.x - s * d.y, a.y + s * d.x + c * d.y},
      right{a.x + c * d.x + s * d.y, a.y - s * d.x + c * d.y};
  return {leader, {left, a, right}};
}

std::optional<Label> leaderLabel(const BoxRoom& inner, const BoxRoom& leaderRoom, const LabelSpot& s,
                                 const std::vector<Label>& taken, const std::vector<double>& heights) {
  const std::vector<Box2> keepOff = leaderBoxes(taken);
  const std::vector<Vec2> ts = targets(leaderRoom.region(), s);
  if (ts.empty()) return std::nullopt;
  // A room is where a centre puts the box on the paper, clear of what is taken: a larger
  // box, or a smaller window, has no room where a smaller box, or a larger window, has
  // none. Most slots that come here have no room at all (MODERN_Cooker_1: 32k of 36k rooms
  // empty), so the smallest size is asked first, in one window about every target.
  const size_t smallest = heights.size() - 1;
  const auto freeAt = [&](size_t j, bool vertical, const Box2& window) {
    return freeFor(inner, taken, halfSize(s.text, heights[j], vertical), window, keepOff);
  };
  const bool noRoom[] = {freeAt(smallest, false, reachOf(ts)).empty(),
                         freeAt(smallest, true, reachOf(ts)).empty()};
  if (noRoom[0] && noRoom[1]) return std::nullopt;
  // The room for each target, size and direction, the same for both gaps: made once.
  std::vector<std::optional<Region2d>> rooms(ts.size() * heights.size() * 2);
  const auto roomAt = [&](size_t i, size_t j, bool vertical) -> const Region2d& {
    const auto at = [&](size_t k) -> std::optional<Region2d>& {
      return rooms[(i * heights.size() + k) * 2 + vertical];
    };
    if (!at(smallest))
      at(smallest) = noRoom[vertical] ? Region2d{} : freeAt(smallest, vertical, reachOf({ts[i]}));
    if (!at(j)) at(j) = at(smallest)->empty() ? Region2d{} : freeAt(j, vertical, reachOf({ts[i]}));
    return *at(j);
  };
  for (const double gap : kLeaderGaps)
    for (size_t i = 0; i < ts.size(); ++i) {
      const Vec2 t = ts[i];
      // The paths only once a label has room somewhere: most slots left without a label
      // have none, and the paths are the costly part (all pairs of bends).
      std::optional<Field> field;
      Routes paths;
      for (size_t j = 0; j < heights.size(); ++j)
        for (const bool vertical : {false, true}) {
          const double height = heights[j];
          const Vec2 half = halfSize(s.text, height, vertical);
          const Region2d& room = roomAt(i, j, vertical);
          if (room.empty()) continue;
          if (!field) field.emplace(leaderRoom.region(), taken, t, gap), paths = shortestPaths(*field, t);
          Vec2 centre;
          Stroke leader = shortestLeader(*field, paths, centres(room, t), half, centre);
          if (leader.empty()) continue;
          Label label = setLabel(s.text, centre, height, vertical);
          for (Stroke& stroke : leaderStrokes(leader)) label.strokes.push_back(std::move(stroke));
          label.leader = std::move(leader);
          return label;
        }
    }
  return std::nullopt;
}

bool leaderMayFit(const BoxRoom& inner, const BoxRoom& leaderRoom, const LabelSpot& s,
                  const std::vector<Label>& taken) {
  const std::vector<Vec2> ts = targets(leaderRoom.region(), s);
  if (ts.empty()) return false;
  // leaderLabel's first question, at the smallest size: the same query, so leaderLabel
  // then answers it from the room's memory.
  const std::vector<Box2> keepOff = leaderBoxes(taken);
  for (const bool vertical : {false, true})
    if (!freeFor(inner, taken, halfSize(s.text, kMinLabelHeight, vertical), reachOf(ts), keepOff).empty())
      return true;
  return false;
}

}  // namespace sliceform
