// SPDX-License-Identifier: LGPL-2.1-or-later
#include "bindings/convert.hpp"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>

#include <sstream>

#include "support/error.hpp"
#include "support/occt_guard.hpp"

namespace sliceform {

TopoDS_Shape shapeFromBrep(const std::string& brep) {
  if (brep.empty()) throw Error(ErrorKind::BadInput, "the BREP string is empty");
  return occtGuard("reading the BREP string", [&] {
    std::istringstream in(brep);
    TopoDS_Shape shape;
    BRep_Builder builder;
    BRepTools::Read(shape, in, builder);
    if (shape.IsNull()) throw Error(ErrorKind::BadInput, "the BREP string holds no shape");
    return shape;
  });
}

std::string brepFromShape(const TopoDS_Shape& shape) {
  if (shape.IsNull()) return {};
  std::ostringstream out;
  BRepTools::Write(shape, out);
  return out.str();
}

Mesh meshFromLists(const std::vector<Triple>& points, const std::vector<Index3>& triangles) {
  Mesh mesh;
  mesh.vertices.reserve(points.size());
  for (const Triple& p : points) mesh.vertices.push_back(toVec(p));
  mesh.triangles.assign(triangles.begin(), triangles.end());
  return mesh;
}

}  // namespace sliceform
