// SPDX-License-Identifier: LGPL-2.1-or-later
// Where a point of a face's surface lies on the face: inside, outside, or on its boundary.
// The face's wires are made polygons in its parameters once (BRepTopAdaptor_FClass2d), and
// a point is placed by them where it is clear of them by more than their deflection; else
// (and where OCCT could not make them) by BRepClass_FaceClassifier, as the polygons' own
// test then asks. The classifier alone explored the face's topology and intersected every
// edge with a ray, for each point: 9 % of occt-misc Bottom.brep's run.
#pragma once

#include <BRepAdaptor_Surface.hxx>
#include <TopAbs_State.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Pnt.hxx>

#include <memory>
#include <mutex>

class BRepTopAdaptor_FClass2d;

namespace sliceform {

// The parameters of `p`, a point of `s`, on the surfaces the face-by-face route makes curves
// on (planes, cylinders, cones, spheres, tori; on a spindle torus the circle past the axis
// where the point is nearer it); false on a surface of another kind.
bool surfaceParameters(const BRepAdaptor_Surface& s, const gp_Pnt& p, double& u, double& v);

class FaceInside {
 public:
  // `face`'s parameter box, and `classified`: the face as the classifiers read it (of a
  // plane, a copy with its edges' 2D curves stored: withPlaneCurves).
  FaceInside(const TopoDS_Face& face, const TopoDS_Face& classified);
  ~FaceInside();
  FaceInside(const FaceInside&) = delete;
  FaceInside& operator=(const FaceInside&) = delete;

  // Where `p`, a point of the face's surface `s`, lies; ON on a surface of a kind the
  // face-by-face route makes no curves on. From any thread.
  TopAbs_State classify(const BRepAdaptor_Surface& s, const gp_Pnt& p) const;

 private:
  TopoDS_Face face_;                                   // the classified one
  double uv_[4];                                       // the face's parameter box: u min, u max, v min, v max
  std::unique_ptr<BRepTopAdaptor_FClass2d> polygons_;  // null where OCCT could not make them
  // FClass2d's Perform is const but reads its sequences by index, and an OCCT sequence
  // moves its own cursor to the item found (NCollection_BaseSequence::Find): two threads
  // at once crashed (occt-misc CrankArm.brep, one run in twelve).
  mutable std::mutex lock_;
};

}  // namespace sliceform
