// SPDX-License-Identifier: LGPL-2.1-or-later
// Sections of a free-form face (a B-spline, a surface of revolution, ...) by parallel
// planes, traced on the face's own parameters instead of walked by OCCT. The height
// n·S(u, v) of the surface along the planes' normal is sampled once, on a grid over the
// face's parameter box, for every plane. A plane's contour is then found cell by cell
// (marching squares); each of its points is put on the exact surface and plane (Newton's
// method along the grid line it crosses), and each contour is interpolated by a cubic
// B-spline through as few of those points as keep all of them within 1 µm.
//
// OCCT's walk of the same face (BRepAlgoAPI_Section, its lines approximated to 0.1 nm) took
// 5-13 ms a plane and face on occt-misc Ball.brep and Pump_TopCover.brep, 18 ms on
// linkrods.step: most of those parts' exact patches.
//
// Each contour is cut where it crosses the face's boundary (trimmed, with holes, or the
// box's border itself), found on the polygon of the edges' curves on the face and then
// exactly on the edge's 3D curve, where the route's crossings of that edge are: a file's
// edge may stray from its face's border (0.04 mm on linkrods.step). The pieces inside are
// kept. Not sure of a plane, and the caller asks OCCT: a saddle of the height within a cell
// on the plane, a point Newton's method does not put on the plane, a crossing of the
// boundary not found on its edge, pieces whose insides do not alternate, a contour no
// B-spline fits.
#pragma once

#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Dir.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>

#include <optional>
#include <vector>

#include "slicing/face_by_face.hpp"

namespace sliceform {

class TracedFace {
 public:
  // mm: two points of a contour, or two crossings of the boundary, closer than this are one.
  static constexpr double kSame = 1e-6;

  // Samples the face and its boundary; empty() where its parameters are unbounded or an
  // edge has no curve on it.
  TracedFace(const TopoDS_Face& face, const gp_Dir& n);
  bool empty() const { return u_.empty(); }

  // The face's section by the plane n·p = d: its edges, each with its vertices (an open
  // contour's at its ends, on the face's edges; a closed one's, one vertex twice); nullopt
  // where unsure. Only reads the samples: several threads may cut at once.
  std::optional<std::vector<FaceByFace::AloneEdge>> cut(double d) const;

 private:
  // One contour of a plane: its exact points in order, their parameters on the face, and
  // the grid cell each piece between two of them lies in (piece k: points k to k + 1, and
  // for a closed one the last back to the first).
  struct Contour {
    std::vector<gp_Pnt> p;
    std::vector<gp_Pnt2d> uv;
    std::vector<int> cell;
    bool closed = false;
  };
  std::optional<std::vector<Contour>> contours(double d) const;
  // The pieces of a contour inside the face, each from the face's boundary to the boundary
  // (or the whole closed contour); nullopt where unsure.
  std::optional<std::vector<Contour>> inside(const Contour& c, double d) const;
  bool contains(const gp_Pnt2d& uv) const;  // by the boundary's polygon, even-odd

  TopoDS_Face face_;  // each cut evaluates it through its own adaptor: a B-spline's cache
                      // is written by every evaluation
  gp_Dir n_;
  std::vector<double> u_, v_;  // the grid's parameters
  std::vector<double> h_;      // n·S at each grid point, u fastest
  // The face's boundary in (u, v): each edge's curve on the face as a polygon of sides, and
  // per grid cell the sides whose box meets it.
  struct Side {
    gp_Pnt2d a, b;
    int edge;       // into edges_
    double ta, tb;  // the edge's parameters at a and b
  };
  std::vector<TopoDS_Edge> edges_;
  std::vector<Side> sides_;
  std::vector<std::vector<int>> cellSides_;
};

}  // namespace sliceform
