// SPDX-License-Identifier: LGPL-2.1-or-later
// What crosses between Python and the core: shapes as BREP strings (what FreeCAD's
// Part.Shape.exportBrepToString gives), meshes as point lists and index triples, vectors
// as 3-tuples.
#pragma once

#include <pybind11/pybind11.h>
#include <TopoDS_Shape.hxx>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/vec.hpp"
#include "model/mesh.hpp"

namespace sliceform {

using Triple = std::array<double, 3>;
using Index3 = std::array<uint32_t, 3>;

inline Vec3 toVec(const Triple& t) {
  return {t[0], t[1], t[2]};
}
inline pybind11::tuple toTuple(const Vec3& v) {
  return pybind11::make_tuple(v.x, v.y, v.z);
}

// Throws BadInput for an empty string or one that holds no shape.
TopoDS_Shape shapeFromBrep(const std::string& brep);
std::string brepFromShape(const TopoDS_Shape& shape);  // "" for a null shape
Mesh meshFromLists(const std::vector<Triple>& points, const std::vector<Index3>& triangles);

}  // namespace sliceform
