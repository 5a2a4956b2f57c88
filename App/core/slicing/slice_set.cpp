// SPDX-License-Identifier: LGPL-2.1-or-later
#include "slicing/slice_set.hpp"

#include <cmath>
#include <string>

#include "support/error.hpp"

namespace sliceform {

SliceFrame makeSliceFrame(Vec3 normal, Vec3 up) {
  const double nn = norm(normal), nu = norm(up);
  if (!(nn > 0) || !(nu > 0) || !std::isfinite(nn) || !std::isfinite(nu))
    throw Error(ErrorKind::BadParameter, "a slicing direction must be a finite non-zero vector");
  normal = normalized(normal);
  up = normalized(up);
  if (std::fabs(dot(normal, up)) > 1e-9)
    throw Error(ErrorKind::BadParameter,
                "the up direction must be orthogonal to the slicing direction (their angle is " +
                    std::to_string(std::acos(dot(normal, up)) * 180 / M_PI) + " degrees)");
  SliceFrame frame;
  frame.normal = normal;
  frame.yAxis = up;
  frame.xAxis = cross(up, normal);  // so that xAxis × yAxis = normal
  return frame;
}

SliceFrame makeSliceFrame(Vec3 normal) {
  const double nn = norm(normal);
  if (!(nn > 0) || !std::isfinite(nn))
    throw Error(ErrorKind::BadParameter, "a slicing direction must be a finite non-zero vector");
  const Vec3 n = normalized(normal);
  const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Vec3 best = axes[2];
  for (int i = 2; i >= 0; --i) {
    if (std::fabs(dot(axes[i], n)) < std::fabs(dot(best, n))) best = axes[i];
  }
  const Vec3 up = best - n * dot(best, n);  // Gram-Schmidt: the part of the axis orthogonal to n
  return makeSliceFrame(n, up);
}

std::vector<double> uniformPositions(double lo, double hi, int count) {
  if (count < 1) throw Error(ErrorKind::BadParameter, "the number of slices must be at least 1");
  if (!(hi > lo)) throw Error(ErrorKind::BadParameter, "the model has no extent along the slicing direction");
  std::vector<double> out(count);
  const double step = (hi - lo) / count;
  for (int i = 0; i < count; ++i) out[i] = lo + (i + 0.5) * step;
  return out;
}

double lineX(const SliceFrame& frame, const SliceFrame& other, double position) {
  return position * dot(other.normal, frame.xAxis);
}

}  // namespace sliceform
