// SPDX-License-Identifier: LGPL-2.1-or-later
// Flat polygons with holes as triangles, for the glTF assembly. A patch's outline is already
// a polygon (within 0.01 mm of an exact face), so meshing its BRep face again is not needed:
// BRepMesh spent about 1 s and 180 MB on rocker-arm's 65 polygon faces of 400 edges each.
// The triangulation is GLU's tessellator (SGI's sweep-line code in Mesa), which handles
// holes and touching loops by winding rule.
#pragma once

#include <array>
#include <vector>

#include "geometry/vec.hpp"

namespace sliceform {

struct Triangles {
  std::vector<Vec3> points;                 // the loops' points, then any GLU added
  std::vector<std::array<int, 3>> corners;  // indices into points, counter-clockwise about `normal`
};

// The region the loops enclose by the even-odd rule (outer loops and holes, any direction),
// all in the plane with the given normal. Throws Geometry if GLU reports an error.
Triangles triangulate(const std::vector<std::vector<Vec3>>& loops, const Vec3& normal);

}  // namespace sliceform
