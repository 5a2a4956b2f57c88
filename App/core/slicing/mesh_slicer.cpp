// SPDX-License-Identifier: LGPL-2.1-or-later
#include "slicing/mesh_slicer.hpp"

#include <algorithm>
#include <sstream>

#include "support/error.hpp"
#include "support/parallel.hpp"

namespace sliceform {
namespace {

// A segment of one triangle's section. It runs from `from` to `to`, oriented by the
// triangle so that, for an outward-facing mesh, the material is on its left.
struct Segment {
  uint64_t fromEdge, toEdge;
  Vec2 from, to;
};

struct PlaneResult {
  Region2d region;
  MeshSliceStats stats;
};

class PlaneSlicer {
 public:
  PlaneSlicer(const Mesh& mesh, const SliceFrame& frame) : mesh_(mesh), frame_(frame) {}

  PlaneResult slice(double position, const std::vector<uint32_t>& triangles) const {
    std::vector<Segment> segments;
    segments.reserve(triangles.size());
    for (uint32_t t : triangles) cutTriangle(mesh_.triangles[t], position, segments);
    return chain(segments);
  }

 private:
  // The point where the plane crosses edge (a, b), computed from the lower vertex id so the
  // two triangles sharing the edge get bit-identical points.
  Vec2 crossing(uint32_t a, uint32_t b, double position) const {
    if (a > b) std::swap(a, b);
    const Vec3& pa = mesh_.vertices[a];
    const Vec3& pb = mesh_.vertices[b];
    const double da = frame_.position(pa) - position, db = frame_.position(pb) - position;
    return frame_.to2d(pa + (pb - pa) * (da / (da - db)));
  }

  void cutTriangle(const std::array<uint32_t, 3>& t, double position, std::vector<Segment>& out) const {
    // A vertex on the plane counts as above: every vertex has a side, so each crossing
    // edge is crossed exactly once and the loops close (symbolic perturbation).
    bool above[3];
    for (int i = 0; i < 3; ++i) above[i] = frame_.position(mesh_.vertices[t[i]]) >= position;
    if (above[0] == above[1] && above[1] == above[2]) return;
    int down = -1, up = -1;  // edges (i, i+1) going above->below and below->above
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      if (above[i] && !above[j]) down = i;
      if (!above[i] && above[j]) up = i;
    }
    const uint32_t d0 = t[down], d1 = t[(down + 1) % 3], u0 = t[up], u1 = t[(up + 1) % 3];
    out.push_back({edgeKey(d0, d1), edgeKey(u0, u1), crossing(d0, d1, position), crossing(u0, u1, position)});
  }

  // Joins segments that cross the same mesh edge. On a closed manifold mesh every crossed
  // edge is shared by exactly two segments, so every chain closes.
  static PlaneResult chain(const std::vector<Segment>& segments) {
    PlaneResult result;
    result.stats.segments = segments.size();
    // (edge, segment end) pairs, end = 2 * segment + (0 for `from`, 1 for `to`).
    std::vector<std::pair<uint64_t, uint32_t>> ends;
    ends.reserve(2 * segments.size());
    for (uint32_t s = 0; s < segments.size(); ++s) {
      ends.push_back({segments[s].fromEdge, 2 * s});
      ends.push_back({segments[s].toEdge, 2 * s + 1});
    }
    std::sort(ends.begin(), ends.end());
    constexpr uint32_t kNone = UINT32_MAX;
    std::vector<uint32_t> partner(ends.size(), kNone);
    for (size_t i = 0; i < ends.size();) {
      size_t j = i;
      while (j < ends.size() && ends[j].first == ends[i].first) ++j;
      // Pairs in order; a non-manifold edge (4, 6... ends) pairs arbitrarily but closes.
      for (size_t k = i; k + 1 < j; k += 2) {
        partner[ends[k].second] = ends[k + 1].second;
        partner[ends[k + 1].second] = ends[k].second;
      }
      i = j;
    }

    std::vector<Region2d::Loop> loops;
    std::vector<char> used(segments.size(), 0);
    bool consistent = true;
    for (uint32_t start = 0; start < segments.size(); ++start) {
      if (used[start]) continue;
      Region2d::Loop loop;
      uint32_t s = start;
      bool forward = true, closed = false, loopConsistent = true;
      while (true) {
        used[s] = 1;
        const Segment& seg = segments[s];
        loop.push_back(forward ? seg.from : seg.to);
        const uint32_t exitEnd = 2 * s + (forward ? 1 : 0);
        const uint32_t next = partner[exitEnd];
        if (next == kNone) break;
        s = next / 2;
        // Entering a segment at its `from` end keeps the direction of travel.
        forward = (next % 2) == 0;
        loopConsistent = loopConsistent && forward;
        if (s == start) {
          closed = true;
          break;
        }
        if (used[s]) break;  // joined a chain already walked: cannot happen on a closed mesh
      }
      if (!closed) {
        ++result.stats.openChains;
        continue;
      }
      ++result.stats.loops;
      if (!loopConsistent) ++result.stats.inconsistentLoops;
      consistent = consistent && loopConsistent;
      loops.push_back(std::move(loop));
    }
    // Consistent orientation lets overlapping shells unite (non-zero winding); a mesh with
    // flipped triangles still slices right under even-odd, as long as shells don't overlap.
    result.region = Region2d::fromLoops(loops, consistent ? FillRule::NonZero : FillRule::EvenOdd);
    return result;
  }

  const Mesh& mesh_;
  const SliceFrame& frame_;
};

}  // namespace

std::vector<double> slicePositions(const Mesh& mesh, const SliceFrame& frame, int count) {
  const Interval range = mesh.extent(frame.normal);
  return uniformPositions(range.lo, range.hi, count);
}

SliceSet sliceMesh(const Mesh& mesh, const SliceFrame& frame, const std::vector<double>& positions,
                   MeshSliceStats* stats) {
  if (!std::is_sorted(positions.begin(), positions.end()))
    throw Error(ErrorKind::BadParameter, "slice positions must be sorted");
  // Bucket triangles by the planes they span: each triangle is visited once, and each plane
  // sees only the triangles that cross it.
  std::vector<std::vector<uint32_t>> buckets(positions.size());
  for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (uint32_t v : mesh.triangles[t]) {
      const double d = frame.position(mesh.vertices[v]);
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
    // Planes with lo < z <= hi are crossed (a vertex at z counts as above, see cutTriangle).
    auto first = std::upper_bound(positions.begin(), positions.end(), lo);
    auto last = std::upper_bound(first, positions.end(), hi);
    for (auto it = first; it != last; ++it) buckets[it - positions.begin()].push_back(t);
  }

  SliceSet set;
  set.frame = frame;
  set.interval = positions.size() > 1 ? positions[1] - positions[0] : 0;
  set.slices.resize(positions.size());
  std::vector<MeshSliceStats> planeStats(positions.size());
  const PlaneSlicer slicer(mesh, frame);
  parallelFor(positions.size(), [&](size_t i) {
    PlaneResult r = slicer.slice(positions[i], buckets[i]);
    set.slices[i] = {positions[i], std::move(r.region)};
    planeStats[i] = r.stats;
  });

  MeshSliceStats total;
  for (size_t i = 0; i < planeStats.size(); ++i) {
    const MeshSliceStats& s = planeStats[i];
    if (s.openChains > 0) {
      std::ostringstream msg;
      msg << "the slice at " << positions[i] << " mm meets " << s.openChains
          << " open chain(s): the mesh is not closed there";
      throw Error(ErrorKind::BadInput, msg.str());
    }
    total.segments += s.segments;
    total.loops += s.loops;
    total.inconsistentLoops += s.inconsistentLoops;
  }
  if (stats) *stats = total;
  return set;
}

}  // namespace sliceform
