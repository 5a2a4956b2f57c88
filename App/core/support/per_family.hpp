// SPDX-License-Identifier: LGPL-2.1-or-later
// PerFamily<T>: one T for each family of patches, looked up by Family, so that code about
// one patch picks its frame, slices or cylinders by the patch's family instead of writing
// `family == Family::U ? a : b` (and the mirror image for the other family) at every use.
#pragma once

#include "slicing/slice_set.hpp"  // Family

namespace sliceform {

// The family a patch of `f` hinges with.
constexpr Family other(Family f) {
  return f == Family::U ? Family::V : Family::U;
}

// 0 for U, 1 for V: where a family is a number (keys, array axes).
constexpr int familyIndex(Family f) {
  return f == Family::U ? 0 : 1;
}
constexpr Family familyAt(int i) {
  return i == 0 ? Family::U : Family::V;
}
// "U" or "V", as patch ids and report.json name the families.
constexpr const char* familyName(Family f) {
  return f == Family::U ? "U" : "V";
}

// T may be a reference, to look up two objects held elsewhere.
template <class T>
struct PerFamily {
  T u, v;

  T& operator[](Family f) { return f == Family::U ? u : v; }
  const T& operator[](Family f) const { return f == Family::U ? u : v; }
};

}  // namespace sliceform
