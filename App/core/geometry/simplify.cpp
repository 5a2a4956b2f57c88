// SPDX-License-Identifier: LGPL-2.1-or-later
#include "geometry/simplify.hpp"

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/ring.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace sliceform {

Region2d simplified(const Region2d& region, double tolerance) {
  namespace bg = boost::geometry;
  using Point = bg::model::d2::point_xy<double>;
  using Ring = bg::model::ring<Point>;  // closed: the first point again at the end
  std::vector<Region2d::Loop> loops;
  for (const Region2d::Loop& loop : region.loops()) {
    Ring ring, simpler;
    for (const Vec2& p : loop) ring.push_back({p.x, p.y});
    ring.push_back(ring.front());
    bg::simplify(ring, simpler, tolerance);
    if (simpler.size() < 4) {
      loops.push_back(loop);
      continue;
    }
    loops.emplace_back();
    for (size_t i = 0; i + 1 < simpler.size(); ++i) loops.back().push_back({simpler[i].x(), simpler[i].y()});
  }
  return Region2d::fromLoops(loops, FillRule::EvenOdd);
}

bool isCrumb(const Region2d::Loop& hole, double width) {
  return std::abs(Region2d::signedArea(hole)) < Region2d::perimeter(hole) * width / 2;
}

Region2d withoutCrumbs(const Region2d& region, double width) {
  std::vector<Region2d::Loop> loops = region.loops();
  const auto crumb = [&](const Region2d::Loop& l) {
    return Region2d::signedArea(l) < 0 && isCrumb(l, width);
  };
  if (std::none_of(loops.begin(), loops.end(), crumb)) return region;
  loops.erase(std::remove_if(loops.begin(), loops.end(), crumb), loops.end());
  return Region2d::fromLoops(loops, FillRule::EvenOdd);
}

}  // namespace sliceform
