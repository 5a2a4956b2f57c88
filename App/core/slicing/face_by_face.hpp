// SPDX-License-Identifier: LGPL-2.1-or-later
// Plane sections of a solid made face by face, without OCCT's Boolean machinery (its set-up
// of interferences, pave blocks and curve checks was most of a plane's cost on parts of
// planes and cylinders). Each face the plane reaches is intersected with it: analytically
// (IntAna_QuadQuadGeo: planes, cylinders, cones, spheres, tori cut across their axis), or,
// for a torus cut along its axis, by loops interpolated through exact points
// (slicing/torus_section.hpp), both in slicing/surface_sections.hpp; each curve is cut
// where the plane crosses the face's edges, and the pieces inside the face are kept
// (slicing/face_inside.hpp). Pieces of two faces meet at the one vertex made
// for each crossing of their shared edge, so the edges chain into loops by shared vertices.
//
// A face of another kind (B-spline, surface of revolution, a torus cut aslant) is traced on
// its parameters (slicing/traced_section.hpp), and where the trace is unsure, cut by
// BRepAlgoAPI_Section of that face alone with the plane; either way its curves end at the
// same crossing vertices. The route answers nothing where it would have to guess or cannot
// solve, and the caller then asks BRepAlgoAPI_Section of the whole solid: a face on the
// plane, the plane through a vertex of the solid or tangent to a face, a crossing on none
// of a face's curves, a piece on a face's boundary, an end of another face's section at
// no crossing.
#pragma once

#include <Bnd_Box.hxx>
#include <TopTools_HSequenceOfShape.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Dir.hxx>
#include <gp_Pln.hxx>

#include <memory>
#include <optional>
#include <vector>

namespace sliceform {

class TracedFace;
class FaceInside;

// OCCT's section curves of `shape` by the faces of `cutters` (BRepAlgoAPI_Section), as both
// routes that ask OCCT want them: the walking lines approximated with their curves on
// `shape`'s faces, none on the cutters, `shape` only read (other threads share it). A null
// shape where OCCT reports an error, or with `strict` also a warning.
TopoDS_Shape sectionCurves(const TopoDS_Shape& shape, const TopoDS_Shape& cutters, bool strict);

// The edges of OCCT's section by the planes at `d` along `n` (sectionCurves), each on the
// plane nearest its middle (planes lie a slice's spacing apart; an end may be a vertex of
// the solid that claims a loose tolerance). Per plane its edges, nullopt where unsure: an
// edge with its middle or an end more than 10 µm off its plane is not a section (OCCT took
// a loose edge of the solid for one, test::boredLoft), and every plane within the edge's
// tolerance of it is unsure, as OCCT may have matched it to any of them. All nullopt where
// an edge has no curve.
std::vector<std::optional<std::vector<TopoDS_Edge>>> edgesByPlane(const TopoDS_Shape& section,
                                                                  const gp_Dir& n,
                                                                  const std::vector<double>& d);

class FaceByFace {
 public:
  // `solid`'s faces and edges, with where each lies along `normal`, the normal of every
  // plane asked for later. Only reads the solid; `edges` may run on several threads at once.
  FaceByFace(const TopoDS_Shape& solid, const gp_Dir& normal);

  // The section edges of each of `planes` (their normal the one given): empty where a
  // plane misses the solid, a null handle where this route is unsure. A face of another
  // kind is cut by all the planes that reach it in one Boolean.
  std::vector<Handle(TopTools_HSequenceOfShape)> edges(const std::vector<gp_Pln>& planes) const;

  // A section edge of a face cut alone by OCCT, its vertices at its first and last parameter.
  struct AloneEdge {
    TopoDS_Edge edge;
    TopoDS_Vertex first, last;
  };

 private:
  struct Edge {
    TopoDS_Edge edge;
    double lo, hi;  // along the normal, from its bounding box
    double tolerance;
  };
  struct Face {
    TopoDS_Face face;
    // Of a face this route solves, where points of its surface lie on it (face_inside.hpp).
    std::shared_ptr<const FaceInside> inside;
    Bnd_Box box;
    double lo, hi;
    std::vector<int> edges;                    // indices into edges_, each once (a seam too)
    bool solved;                               // cut by this route's own curves (solvedBy)
    std::shared_ptr<const TracedFace> traced;  // of a face not solved: its sections traced,
                                               // null where they cannot be (cutAlone only)
  };
  // Per face and plane, the edges of a face cut alone (nullopt where OCCT was unsure or an
  // edge lies off its plane; empty for the faces this route solves).
  using Alone = std::vector<std::vector<std::optional<std::vector<AloneEdge>>>>;
  // The section edges of planes[k], at d along the normal.
  Handle(TopTools_HSequenceOfShape)
      planeEdges(const gp_Pln& plane, double d, const Alone& alone, size_t k) const;

  gp_Dir normal_;
  std::vector<Edge> edges_;
  std::vector<Face> faces_;
};

}  // namespace sliceform
