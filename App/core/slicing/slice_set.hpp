// SPDX-License-Identifier: LGPL-2.1-or-later
// A slice set: parallel cross-sections of the model along one direction, all expressed in
// one 2D frame so that the union of projections (the paper's p ⊕ p') is a plain 2D union.
#pragma once

#include <vector>

#include "geometry/region2d.hpp"
#include "geometry/vec.hpp"

namespace sliceform {

// The two families of patches: U-patches lie in planes normal to U, V-patches normal to V.
enum class Family { U, V };

// Plane coordinates of a slice set. A point p lies on the slice at position dot(p, normal)
// and has 2D coordinates (dot(p, xAxis), dot(p, yAxis)). The y axis is "up" (W), so a
// hinge, which is parallel to W, is a vertical line x = const in every slice. The frame is
// right-handed: xAxis × yAxis = normal.
struct SliceFrame {
  Vec3 normal{1, 0, 0};
  Vec3 xAxis{0, 1, 0};
  Vec3 yAxis{0, 0, 1};

  double position(const Vec3& p) const { return dot(p, normal); }
  Vec2 to2d(const Vec3& p) const { return {dot(p, xAxis), dot(p, yAxis)}; }
  Vec3 to3d(const Vec2& q, double position) const { return normal * position + xAxis * q.x + yAxis * q.y; }
};

// The frame of slices normal to `normal` with `up` as y axis (the two must be orthogonal;
// both are normalised). Throws BadParameter otherwise.
SliceFrame makeSliceFrame(Vec3 normal, Vec3 up);
// Any up direction orthogonal to `normal` (the world axis least aligned with it).
SliceFrame makeSliceFrame(Vec3 normal);

// The x, in `frame`'s coordinates, of the line where the plane at `position` of the other
// family's frame crosses planes of `frame` (the line of every hinge between the two).
double lineX(const SliceFrame& frame, const SliceFrame& other, double position);

// `count` positions at the centres of equal cells of [lo, hi]: the first and last slices sit
// half an interval inside the model, where its sections are not degenerate.
std::vector<double> uniformPositions(double lo, double hi, int count);

struct Slice {
  double position = 0;  // along the frame normal, mm
  Region2d region;      // the material of the section, in frame coordinates
};

struct SliceSet {
  SliceFrame frame;
  double interval = 0;  // distance between consecutive slices, mm
  std::vector<Slice> slices;
};

}  // namespace sliceform
