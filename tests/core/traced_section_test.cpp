// SPDX-License-Identifier: LGPL-2.1-or-later
#include <gtest/gtest.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepGProp.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Pln.hxx>

#include "slicing/traced_section.hpp"
#include "test_support.hpp"

namespace sliceform {
namespace {

double length(const TopoDS_Shape& edges) {
  GProp_GProps props;
  BRepGProp::LinearProperties(edges, props);
  return props.Mass();
}

// The traced sections of a loft's side (one B-spline face) across and aslant: bounded by
// its parameter box, and bored across (two holes, where each contour is cut at the
// boundary). The trace answers every plane; its edges lie on the plane and within 1 µm of
// the face, and are as long as OCCT's section of the face by that plane.
TEST(TracedSection, FollowsTheFaceAsOcctsSectionDoes) {
  for (const bool bored : {false, true}) {
    TopoDS_Face side;
    for (TopExp_Explorer it(bored ? test::boredLoft() : test::loft(), TopAbs_FACE); it.More(); it.Next())
      if (BRepAdaptor_Surface(TopoDS::Face(it.Current())).GetType() == GeomAbs_BSplineSurface)
        side = TopoDS::Face(it.Current());
    ASSERT_FALSE(side.IsNull());
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(side);
    int cutByBore = 0;
    for (const gp_Dir n : {gp_Dir(1, 0, 0), gp_Dir(1, 0, 0.5), gp_Dir(0, 1, 0.2), gp_Dir(0, 0, 1)}) {
      const TracedFace traced(side, n);
      ASSERT_FALSE(traced.empty());
      for (int k = 0; k < 12; ++k) {
        // Across the loft (x from -10 to 13), none through a vertex of its seam (y = 0).
        const double d = -11 + 22 * (k + 0.5) / 12;
        SCOPED_TRACE(std::string(bored ? "bored, " : "") + "normal " + std::to_string(n.X()) + " " +
                     std::to_string(n.Z()) + ", at " + std::to_string(d));
        const auto edges = traced.cut(d);
        ASSERT_TRUE(edges.has_value());
        TopoDS_Compound all;
        BRep_Builder builder;
        builder.MakeCompound(all);
        for (const FaceByFace::AloneEdge& e : *edges) {
          builder.Add(all, e.edge);
          const BRepAdaptor_Curve c(e.edge);
          for (int i = 0; i <= 20; ++i) {
            const gp_Pnt p = c.Value(c.FirstParameter() + (c.LastParameter() - c.FirstParameter()) * i / 20);
            EXPECT_NEAR(n.XYZ().Dot(p.XYZ()), d, 1e-6);
            EXPECT_LE(GeomAPI_ProjectPointOnSurf(p, surface).LowerDistance(), 1e-3);
          }
        }
        const gp_Pnt origin(n.XYZ() * d);
        // OCCT's section of the face alone, as the route asked for it before.
        const TopoDS_Shape occt =
            sectionCurves(side, BRepBuilderAPI_MakeFace(gp_Pln(origin, n), -50, 50, -50, 50).Face(), false);
        ASSERT_FALSE(occt.IsNull());
        EXPECT_NEAR(length(all), length(occt), 1e-4 * length(occt) + 1e-6);
        cutByBore += edges->size() > 1 ? 1 : 0;
      }
    }
    if (bored) {
      EXPECT_GT(cutByBore, 0);
    }  // some contours were cut where they cross a hole
  }
}

}  // namespace
}  // namespace sliceform
