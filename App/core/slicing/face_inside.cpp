// SPDX-License-Identifier: LGPL-2.1-or-later
#include "slicing/face_inside.hpp"

#include <BRepClass_FaceClassifier.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <ElCLib.hxx>
#include <ElSLib.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>

#include <cmath>

namespace sliceform {
namespace {

// The parameters of a point on a torus. ElSLib takes the tube's circle on the point's side
// of the axis; on a spindle torus (R < r) the point may lie on the circle past the axis,
// at u + π: the one whose circle the point is nearer is its own.
void torusParameters(const gp_Torus& torus, const gp_Pnt& p, double& u, double& v) {
  ElSLib::Parameters(torus, p, u, v);
  const double big = torus.MajorRadius(), small = torus.MinorRadius();
  if (big >= small) return;
  const gp_Ax3& frame = torus.Position();
  const gp_XYZ d = p.XYZ() - frame.Location().XYZ();
  const double x = d.Dot(frame.XDirection().XYZ()), y = d.Dot(frame.YDirection().XYZ());
  const double z = d.Dot(frame.Direction().XYZ()), across = std::hypot(x, y);
  if (std::abs(std::hypot(across + big, z) - small) < std::abs(std::hypot(across - big, z) - small))
    u = std::atan2(y, x) + M_PI, v = std::atan2(z, -across - big);
}

}  // namespace

FaceInside::FaceInside(const TopoDS_Face& face, const TopoDS_Face& classified) : face_(classified) {
  BRepTools::UVBounds(face, uv_[0], uv_[1], uv_[2], uv_[3]);
  try {
    polygons_ = std::make_unique<BRepTopAdaptor_FClass2d>(classified, Precision::PConfusion());
  } catch (const Standard_Failure&) {
    polygons_.reset();  // classified by BRepClass_FaceClassifier alone
  }
}

FaceInside::~FaceInside() = default;

bool surfaceParameters(const BRepAdaptor_Surface& s, const gp_Pnt& p, double& u, double& v) {
  switch (s.GetType()) {
    case GeomAbs_Plane:
      ElSLib::Parameters(s.Plane(), p, u, v);
      return true;
    case GeomAbs_Cylinder:
      ElSLib::Parameters(s.Cylinder(), p, u, v);
      return true;
    case GeomAbs_Cone:
      ElSLib::Parameters(s.Cone(), p, u, v);
      return true;
    case GeomAbs_Sphere:
      ElSLib::Parameters(s.Sphere(), p, u, v);
      return true;
    case GeomAbs_Torus:
      torusParameters(s.Torus(), p, u, v);
      return true;
    default:
      return false;
  }
}

TopAbs_State FaceInside::classify(const BRepAdaptor_Surface& s, const gp_Pnt& p) const {
  double u = 0, v = 0;
  if (!surfaceParameters(s, p, u, v)) return TopAbs_ON;  // no curves are made on other surfaces
  if (s.IsUPeriodic()) u = ElCLib::InPeriod(u, uv_[0], uv_[0] + s.UPeriod());
  if (s.IsVPeriodic()) v = ElCLib::InPeriod(v, uv_[2], uv_[2] + s.VPeriod());
  if (polygons_) {
    const std::lock_guard<std::mutex> lock(lock_);
    return polygons_->Perform(gp_Pnt2d(u, v), Standard_False);  // u, v put in the period above
  }
  const BRepClass_FaceClassifier classifier(face_, gp_Pnt2d(u, v), Precision::PConfusion());
  return classifier.State();
}

}  // namespace sliceform
