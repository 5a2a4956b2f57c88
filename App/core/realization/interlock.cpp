// SPDX-License-Identifier: LGPL-2.1-or-later
#include "realization/interlock.hpp"

namespace sliceform {
namespace {

constexpr double kNudge = 1e-3;  // mm a crossing point moves into its own hole

bool inside(const Region2d::Loop& loop, Vec2 pt) {
  bool in = false;
  for (size_t i = 0, n = loop.size(); i < n; ++i) {
    const Vec2& p = loop[i];
    const Vec2& q = loop[(i + 1) % n];
    if ((p.y > pt.y) != (q.y > pt.y) && pt.x < p.x + (pt.y - p.y) * (q.x - p.x) / (q.y - p.y)) in = !in;
  }
  return in;
}

// Heights where `hole` crosses the vertical line x = c, each nudged into the hole. The
// side test is half-open (x > c against x <= c), as in Region2d::intervalsOnLine.
std::vector<double> crossings(const Region2d::Loop& hole, double c) {
  std::vector<double> out;
  const bool clockwise = Region2d::signedArea(hole) < 0;
  for (size_t i = 0, n = hole.size(); i < n; ++i) {
    const Vec2& p = hole[i];
    const Vec2& q = hole[(i + 1) % n];
    if ((p.x > c) == (q.x > c)) continue;
    const double y = p.y + (c - p.x) * (q.y - p.y) / (q.x - p.x);
    // The hole lies left of a counter-clockwise edge and right of a clockwise one; going
    // up (+y) from the crossing is left of the edge when it runs towards -x.
    const bool upIsLeft = q.x < p.x;
    out.push_back(y + (upIsLeft != clockwise ? kNudge : -kNudge));
  }
  return out;
}

bool spans(const Box2& box, double x) {
  return !box.empty && box.min.x <= x && x <= box.max.x;
}

}  // namespace

HoleLoops holeLoops(const Region2d& slotted, double position) {
  HoleLoops out;
  out.position = position;
  for (Region2d::Loop& loop : slotted.loops()) {
    if (Region2d::signedArea(loop) >= 0) continue;
    Box2 box;
    for (const Vec2& p : loop) {
      if (box.empty) box.min = box.max = p, box.empty = false;
      box.min = {std::min(box.min.x, p.x), std::min(box.min.y, p.y)};
      box.max = {std::max(box.max.x, p.x), std::max(box.max.y, p.y)};
    }
    out.holes.push_back(std::move(loop));
    out.boxes.push_back(box);
  }
  return out;
}

int interlockCount(const HoleLoops& a, const SliceFrame& uFrame, const HoleLoops& b,
                   const SliceFrame& vFrame) {
  if (a.holes.empty() || b.holes.empty()) return 0;
  const double xa = lineX(uFrame, vFrame, b.position);  // H in A's coordinates
  const double xb = lineX(vFrame, uFrame, a.position);  // H in B's coordinates
  int count = 0;
  for (size_t i = 0; i < a.holes.size(); ++i) {
    if (!spans(a.boxes[i], xa)) continue;
    const std::vector<double> ys = crossings(a.holes[i], xa);
    for (size_t j = 0; j < b.holes.size(); ++j) {
      if (!spans(b.boxes[j], xb)) continue;
      int in = 0;
      for (const double y : ys) in += inside(b.holes[j], {xb, y}) ? 1 : 0;
      count += in % 2;
    }
  }
  return count;
}

}  // namespace sliceform
