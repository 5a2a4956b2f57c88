// SPDX-License-Identifier: LGPL-2.1-or-later
#include "slicing/surface_sections.hpp"

#include <ElCLib.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Ellipse.hxx>
#include <Geom_Hyperbola.hxx>
#include <Geom_Line.hxx>
#include <Geom_Parabola.hxx>
#include <IntAna_QuadQuadGeo.hxx>

#include <cmath>
#include <limits>
#include <optional>

#include "slicing/face_inside.hpp"
#include "slicing/torus_section.hpp"

namespace sliceform {
namespace {

constexpr double kTwoPi = 2 * M_PI;

// The parameter range of an unbounded curve that covers `box`: past it the curve is
// outside the face, so the pieces there are classified out.
void boundTo(const Bnd_Box& box, SectionCurve& c) {
  const gp_Pnt centre((box.CornerMin().XYZ() + box.CornerMax().XYZ()) / 2);
  const double reach = centre.Distance(box.CornerMax());
  if (auto line = Handle(Geom_Line)::DownCast(c.curve)) {
    const double t = ElCLib::Parameter(line->Lin(), centre);
    c.first = t - reach - 1, c.last = t + reach + 1;
  } else if (auto parabola = Handle(Geom_Parabola)::DownCast(c.curve)) {
    // |P(t) - P(0)| >= |t|.
    const double t = parabola->Location().Distance(centre) + reach + 1;
    c.first = -t, c.last = t;
  } else if (auto hyperbola = Handle(Geom_Hyperbola)::DownCast(c.curve)) {
    // |P(t) - P(0)| >= a (cosh t - 1).
    const double t =
        std::acosh((hyperbola->Location().Distance(centre) + reach + 1) / hyperbola->MajorRadius() + 1);
    c.first = -t, c.last = t;
  }
}

}  // namespace

bool planeSurfaceCurves(const BRepAdaptor_Surface& s, const gp_Pln& plane, const Bnd_Box& box,
                        std::vector<SectionCurve>& out) {
  const double angular = Precision::Angular(), confusion = Precision::Confusion();
  IntAna_QuadQuadGeo q;
  switch (s.GetType()) {
    case GeomAbs_Plane:
      q.Perform(plane, s.Plane(), angular, confusion);
      break;
    case GeomAbs_Cylinder:
      q.Perform(plane, s.Cylinder(), angular, confusion);
      break;
    case GeomAbs_Cone:
      q.Perform(plane, s.Cone(), angular, confusion);
      break;
    case GeomAbs_Sphere:
      q.Perform(plane, s.Sphere());
      break;
    case GeomAbs_Torus:
      q.Perform(plane, s.Torus(), confusion);
      break;
    default:
      break;
  }
  // A torus along the plane: its loops (slicing/torus_section.hpp).
  if (s.GetType() == GeomAbs_Torus && (!q.IsDone() || q.TypeInter() == IntAna_NoGeometricSolution)) {
    const std::optional<TorusSection> section = torusSection(s.Torus(), plane);
    if (!section) return false;
    for (const Handle(Geom_BSplineCurve) & loop : section->loops) {
      SectionCurve c;
      c.curve = loop;
      c.first = loop->FirstParameter(), c.last = loop->LastParameter();
      c.periodic = true;
      c.tolerance = section->tolerance;
      out.push_back(c);
    }
    return true;
  }
  // B-splines, surfaces of revolution, tori cut aslant: not here (traced, or cutAlone).
  // Walking them with GeomInt_IntSS was tried: as fast as the section's own walk, but its
  // curves made exact patches break rules their polygons keep (occt-misc Bottom.brep: 9
  // patches emitted as polygons instead of 3; MODERN_Sink_1: 9 instead of 2).
  if (s.GetType() > GeomAbs_Torus || !q.IsDone() || q.TypeInter() == IntAna_NoGeometricSolution) return false;
  const IntAna_ResultType type = q.TypeInter();
  if (type == IntAna_Empty) return true;
  // One line on a cylinder or cone, one circle on a torus: the plane is tangent to it.
  if (type == IntAna_Line && q.NbSolutions() < 2 && s.GetType() != GeomAbs_Plane) return false;
  if (type == IntAna_Circle && q.NbSolutions() < 2 && s.GetType() == GeomAbs_Torus) return false;
  for (Standard_Integer i = 1; i <= q.NbSolutions(); ++i) {
    SectionCurve c;
    c.periodic = type == IntAna_Circle || type == IntAna_Ellipse;
    c.first = 0, c.last = kTwoPi;
    switch (type) {
      case IntAna_Line:
        c.curve = new Geom_Line(q.Line(i));
        break;
      case IntAna_Circle:
        c.curve = new Geom_Circle(q.Circle(i));
        break;
      case IntAna_Ellipse:
        c.curve = new Geom_Ellipse(q.Ellipse(i));
        break;
      case IntAna_Parabola:
        c.curve = new Geom_Parabola(q.Parabola(i));
        break;
      case IntAna_Hyperbola:
        c.curve = new Geom_Hyperbola(q.Hyperbola(i));
        break;
      default:
        return false;  // a point, the plane itself
    }
    if (!c.periodic) boundTo(box, c);
    out.push_back(c);
  }
  return true;
}

double footOnCurve(const Geom_Curve& curve, const gp_Pnt& p, double t) {
  double best = curve.Value(t).SquareDistance(p);
  for (int i = 0; i < 8; ++i) {
    gp_Pnt c;
    gp_Vec d1, d2;
    curve.D2(t, c, d1, d2);
    const gp_Vec r(p, c);
    const double slope = r.Dot(d1), bend = d1.SquareMagnitude() + r.Dot(d2);
    if (!(bend > 0)) break;
    const double next = t - slope / bend, distance = curve.Value(next).SquareDistance(p);
    if (!(distance < best)) break;
    best = distance, t = next;
  }
  return t;
}

std::pair<double, double> projectOnSection(const SectionCurve& c, const gp_Pnt& p) {
  double t;
  if (auto line = Handle(Geom_Line)::DownCast(c.curve))
    t = ElCLib::Parameter(line->Lin(), p);
  else if (auto circle = Handle(Geom_Circle)::DownCast(c.curve))
    t = ElCLib::Parameter(circle->Circ(), p);
  else if (auto ellipse = Handle(Geom_Ellipse)::DownCast(c.curve))
    t = footOnCurve(*ellipse, p, ElCLib::Parameter(ellipse->Elips(), p));
  else if (auto parabola = Handle(Geom_Parabola)::DownCast(c.curve))
    t = footOnCurve(*parabola, p, ElCLib::Parameter(parabola->Parab(), p));
  else if (auto hyperbola = Handle(Geom_Hyperbola)::DownCast(c.curve))
    t = footOnCurve(*hyperbola, p, ElCLib::Parameter(hyperbola->Hypr(), p));
  else {
    // A torus's loop: closed, so the projection has a minimum inside it.
    GeomAPI_ProjectPointOnCurve projection(p, c.curve, c.first, c.last);
    if (projection.NbPoints() == 0) return {0, std::numeric_limits<double>::max()};
    return {projection.LowerDistanceParameter(), projection.LowerDistance()};
  }
  return {t, c.curve->Value(t).Distance(p)};
}

namespace {

// Nearer tangent than this a crossing is not given to its nearest curve (grazedFoot): the
// section's curves come together there (a cylinder's two lines lie 2 r sin(phi) apart), and
// the foot is as unsure as the distance is magnified (a thousandfold at this bound).
constexpr double kMinGrazingSine = 1e-3;

// The sine of the angle between the normal of `s` at `p` (a point of it) and `n`, for the
// surfaces planeSurfaceCurves solves; 0 where it has no normal there (an apex, a pole).
double sineToNormal(const BRepAdaptor_Surface& s, const gp_Pnt& p, const gp_Dir& n) {
  double u = 0, v = 0;
  if (!surfaceParameters(s, p, u, v)) return 0;
  gp_Pnt at;
  gp_Vec du, dv;
  s.D1(u, v, at, du, dv);
  const gp_Vec normal = du.Crossed(dv);
  const double length = normal.Magnitude();
  return length > 1e-12 ? (normal / length).Crossed(gp_Vec(n)).Magnitude() : 0;
}

}  // namespace

std::optional<std::pair<size_t, double>> grazedFoot(const BRepAdaptor_Surface& s,
                                                    const std::vector<SectionCurve>& curves,
                                                    const std::vector<double>& budget, const gp_Pnt& p,
                                                    const gp_Dir& n) {
  size_t nearest = curves.size();
  std::pair<double, double> foot{0, std::numeric_limits<double>::max()};
  for (size_t k = 0; k < curves.size(); ++k) {
    const std::pair<double, double> at = projectOnSection(curves[k], p);
    if (at.second < foot.second) foot = at, nearest = k;
  }
  if (nearest == curves.size()) return std::nullopt;
  const double sine = sineToNormal(s, curves[nearest].curve->Value(foot.first), n);
  if (sine < kMinGrazingSine || foot.second * sine > budget[nearest]) return std::nullopt;
  return std::pair{nearest, foot.first};
}

}  // namespace sliceform
