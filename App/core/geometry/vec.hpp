// SPDX-License-Identifier: LGPL-2.1-or-later
// Small value types for points and directions, in millimetres.
#pragma once

#include <cmath>

namespace sliceform {

struct Vec2 {
  double x = 0, y = 0;
};

struct Vec3 {
  double x = 0, y = 0, z = 0;

  Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
  bool operator==(const Vec3& o) const { return x == o.x && y == o.y && z == o.z; }
};

inline double dot(const Vec3& a, const Vec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(const Vec3& a) {
  return std::sqrt(dot(a, a));
}
inline Vec3 normalized(const Vec3& a) {
  return a * (1.0 / norm(a));
}

// A closed range [lo, hi] of a coordinate.
struct Interval {
  double lo = 0, hi = 0;
};

// An axis-aligned box; empty until the first point is added.
struct Box3 {
  Vec3 min{HUGE_VAL, HUGE_VAL, HUGE_VAL};
  Vec3 max{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};

  bool empty() const { return min.x > max.x; }
  void add(const Vec3& p) {
    min = {std::fmin(min.x, p.x), std::fmin(min.y, p.y), std::fmin(min.z, p.z)};
    max = {std::fmax(max.x, p.x), std::fmax(max.y, p.y), std::fmax(max.z, p.z)};
  }
  Vec3 size() const { return max - min; }
  double diagonal() const { return empty() ? 0.0 : norm(size()); }
};

}  // namespace sliceform
