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
// Only for a face bounded by its parameter box (every edge's curve on the face lies on the
// box's border): a contour then ends where it meets the face's edges. Not sure of a plane,
// and the caller asks OCCT: a saddle of the height within a cell on the plane, two points of
// a contour at one place (the plane through a grid point or tangent to the face), a point
// that Newton's method does not put on the plane, a contour no B-spline fits.
#pragma once

#include <TopoDS_Face.hxx>
#include <gp_Dir.hxx>

#include <optional>
#include <vector>

#include "slicing/face_by_face.hpp"

namespace sliceform {

class TracedFace {
 public:
  // Samples the face; empty() when it is not bounded by its parameter box, or fails.
  TracedFace(const TopoDS_Face& face, const gp_Dir& n);
  bool empty() const { return u_.empty(); }

  // The face's section by the plane n·p = d: its edges, each with its vertices (an open
  // contour's at its ends, on the face's edges; a closed one's, one vertex twice); nullopt
  // where unsure. Only reads the samples: several threads may cut at once.
  std::optional<std::vector<FaceByFace::AloneEdge>> cut(double d) const;

 private:
  TopoDS_Face face_;  // each cut evaluates it through its own adaptor: a B-spline's cache
                      // is written by every evaluation
  gp_Dir n_;
  std::vector<double> u_, v_;  // the grid's parameters
  std::vector<double> h_;      // n·S at each grid point, u fastest
};

}  // namespace sliceform
