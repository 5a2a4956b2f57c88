// SPDX-License-Identifier: LGPL-2.1-or-later
// Shared helpers of the core tests: hand-built meshes, OCCT test solids, temporary folders.
#pragma once

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepGProp.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>
#include <gp_Elips.hxx>

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include "geometry/region2d.hpp"
#include "geometry/vec.hpp"
#include "model/mesh.hpp"

namespace sliceform::test {

// An axis-aligned box [lo, lo + size] as 8 vertices and 12 outward-facing triangles.
inline Mesh boxMesh(Vec3 lo, Vec3 size) {
  Mesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back(
        {lo.x + (i & 1 ? size.x : 0), lo.y + (i & 2 ? size.y : 0), lo.z + (i & 4 ? size.z : 0)});
  // Vertex i has x = bit 0, y = bit 1, z = bit 2. Each quad is counter-clockwise seen from
  // outside, split along its first diagonal.
  const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  return m;
}

inline Mesh cubeMesh(double side) {
  return boxMesh({0, 0, 0}, {side, side, side});
}

// The same mesh with every triangle given its own three vertices (an STL triangle soup).
inline Mesh toSoup(const Mesh& mesh) {
  Mesh soup;
  for (const auto& t : mesh.triangles) {
    const auto base = static_cast<uint32_t>(soup.vertices.size());
    for (uint32_t v : t) soup.vertices.push_back(mesh.vertices[v]);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  return soup;
}

// Signed area of a closed polygon (shoelace): positive when counter-clockwise.
template <class Loop>
double signedArea(const Loop& loop) {
  double twice = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const auto& a = loop[i];
    const auto& b = loop[(i + 1) % loop.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return twice / 2;
}

// How far rounding to Clipper's integer grid can move the area of a region with this
// perimeter: every vertex moves by less than one unit.
inline double gridTolerance(double perimeter) {
  return perimeter / Region2d::kUnitsPerMm + 1e-12;
}

// Section areas of the test solids at distance h from their centre.
inline double discArea(double radius, double h) {
  return M_PI * std::fmax(0.0, radius * radius - h * h);
}
// Torus around the slicing axis: an annulus between radii major -/+ sqrt(minor² - h²).
inline double torusArea(double major, double minor, double h) {
  return 4 * M_PI * major * std::sqrt(std::fmax(0.0, minor * minor - h * h));
}

// The area of a shape's faces, mm² (OCCT's surface integration).
inline double area(const TopoDS_Shape& shape) {
  GProp_GProps props;
  BRepGProp::SurfaceProperties(shape, props);
  return props.Mass();
}

inline TopoDS_Shape makeSphere(double radius) {
  return BRepPrimAPI_MakeSphere(radius).Shape();
}

// A torus around the Z axis through the origin.
inline TopoDS_Shape makeTorus(double major, double minor) {
  return BRepPrimAPI_MakeTorus(major, minor).Shape();
}

inline TopoDS_Shape cut(const TopoDS_Shape& a, const TopoDS_Shape& b) {
  BRepAlgoAPI_Cut op(a, b);
  if (!op.IsDone()) throw std::runtime_error("BRepAlgoAPI_Cut failed");
  return op.Shape();
}

// Every edge and vertex of `shape` made to claim `tolerance` mm, in place, as some real
// files' do (1-3 mm: occt-misc MODERN_Sink_1 has a circle claiming 3).
inline void loosen(const TopoDS_Shape& shape, double tolerance) {
  BRep_Builder builder;
  for (TopExp_Explorer e(shape, TopAbs_EDGE); e.More(); e.Next())
    builder.UpdateEdge(TopoDS::Edge(e.Current()), tolerance);
  for (TopExp_Explorer v(shape, TopAbs_VERTEX); v.More(); v.Next())
    builder.UpdateVertex(TopoDS::Vertex(v.Current()), tolerance);
}

// A loft through a circle, an ellipse and a smaller circle: its side is one B-spline face,
// bounded by its parameter box, which the face-by-face route traces (slicing/traced_section.hpp).
inline TopoDS_Shape loft() {
  BRepOffsetAPI_ThruSections loft(Standard_True, Standard_False);
  const auto wire = [](const TopoDS_Edge& e) { return BRepBuilderAPI_MakeWire(e).Wire(); };
  loft.AddWire(wire(BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 10)).Edge()));
  loft.AddWire(
      wire(BRepBuilderAPI_MakeEdge(gp_Elips(gp_Ax2(gp_Pnt(1, 0, 10), gp_Dir(0, 0, 1)), 12, 7)).Edge()));
  loft.AddWire(wire(BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(0, 0, 20), gp_Dir(0, 0, 1)), 6)).Edge()));
  loft.Build();
  return loft.Shape();
}

// The loft bored across: its side face has holes, and the face-by-face route hands it to
// OCCT's section. With `looseness`, every edge and vertex claims that many mm of tolerance
// (loosen), and OCCT's sections of it are often wrong: a face's boundary circle for its
// section, a plane read as missing the solid, faces larger than the solid's section.
inline TopoDS_Shape boredLoft(double looseness = 0) {
  const TopoDS_Shape shape =
      cut(loft(), BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, -20, 9), gp_Dir(0, 1, 0)), 2.5, 40).Shape());
  if (looseness > 0) loosen(shape, looseness);
  return shape;
}

// A sphere of radius outer with a concentric spherical void of radius inner.
inline TopoDS_Shape makeHollowSphere(double outer, double inner) {
  return cut(makeSphere(outer), makeSphere(inner));
}

// Box [0,a] x [0,b] x [0,c] with cylindrical through holes parallel to Z. With `grow` the
// box is [-grow, a + grow] etc. and the holes have radius r - grow: a solid that contains
// every solid within `grow` of the original one (or is contained in it, for grow < 0).
struct Hole {
  double x, y, r;
};
inline TopoDS_Shape makeBoxWithHoles(double a, double b, double c, const std::vector<Hole>& holes,
                                     double grow = 0) {
  TopoDS_Shape shape =
      BRepPrimAPI_MakeBox(gp_Pnt(-grow, -grow, -grow), a + 2 * grow, b + 2 * grow, c + 2 * grow).Shape();
  for (const Hole& h : holes) {
    const gp_Ax2 axis(gp_Pnt(h.x, h.y, -c), gp_Dir(0, 0, 1));
    shape = cut(shape, BRepPrimAPI_MakeCylinder(axis, h.r - grow, 3 * c).Shape());
  }
  return shape;
}

// A hollow box a x b x c with walls `wall` thick, and two square windows through each of
// its four side walls: every slice across it is a frame with holes.
inline TopoDS_Shape makeBoxWithWindows(double a, double b, double c, double wall) {
  TopoDS_Shape shape =
      cut(BRepPrimAPI_MakeBox(a, b, c).Shape(),
          BRepPrimAPI_MakeBox(gp_Pnt(wall, wall, wall), a - 2 * wall, b - 2 * wall, c - 2 * wall).Shape());
  const double s = c / 3;  // window side
  for (int k = 1; k <= 2; ++k) {
    shape = cut(shape, BRepPrimAPI_MakeBox(gp_Pnt(k * a / 3 - s / 2, -1, c / 3), s, b + 2, s).Shape());
    shape = cut(shape, BRepPrimAPI_MakeBox(gp_Pnt(-1, k * b / 3 - s / 2, c / 3), a + 2, s, s).Shape());
  }
  return shape;
}

// A fresh folder under the system temporary folder, removed with everything in it.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
    path_ =
        std::filesystem::temp_directory_path() / ("sliceform_test_" + std::to_string(::getpid()) + "_" +
                                                  std::to_string(stamp) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string file(const std::string& name) const { return (path_ / name).string(); }
  // Writes `content` (text or bytes) to `name` and returns the full path.
  std::string write(const std::string& name, const std::string& content) const {
    const std::string p = file(name);
    std::ofstream(p, std::ios::binary) << content;
    return p;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace sliceform::test
