// SPDX-License-Identifier: LGPL-2.1-or-later
#include "slicing/face_by_face.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <ElCLib.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <tuple>

#include "slicing/face_inside.hpp"
#include "slicing/surface_sections.hpp"
#include "slicing/traced_section.hpp"
#include "support/parallel.hpp"
#include "support/plane_curves.hpp"

namespace sliceform {

namespace {

constexpr double kTwoPi = 2 * M_PI;

std::pair<double, double> along(const Bnd_Box& box, const gp_Dir& n) {
  double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
  for (const double x : {box.CornerMin().X(), box.CornerMax().X()})
    for (const double y : {box.CornerMin().Y(), box.CornerMax().Y()})
      for (const double z : {box.CornerMin().Z(), box.CornerMax().Z()}) {
        const double p = n.XYZ().Dot(gp_XYZ(x, y, z));
        lo = std::min(lo, p), hi = std::max(hi, p);
      }
  return {lo, hi};
}

// How near the plane an end of an edge, or a tangent touch, makes this route unsure, at
// most: the edge's tolerance, or 0.1 µm where the file claims more. OCCT's tolerance is a
// claim about the faces' fit, not about where the plane is: a sink's circle with a 3 mm
// tolerance (occ/MODERN_Sink_1.brep) sent every plane within 3 mm of its seam vertex to
// the Boolean Common, 60-70 ms a plane; that design's exact patches broke rules their
// polygons keep (9 of 19 emitted as polygons, none since).
constexpr double kOnPlane = 1e-4;
// mm an edge of OCCT's cut of a face may lie off its plane, at its middle: its curve is the
// face's intersection with the plane, approximated. Not the edge's tolerance: a loose edge
// of the solid (1-3 mm) lying near a plane came back as that plane's section (a loft's
// boundary circle 0.8 mm below the plane, test::boredLoft).
constexpr double kOffPlane = 1e-2;

// Where the plane n·p = d crosses an edge, appended to `out`; false where the route is
// unsure: an end of the edge on the plane (a vertex of the solid), a tangent touch.
bool crossings(const TopoDS_Edge& edge, double edgeTolerance, const gp_Dir& n, double d,
               std::vector<gp_Pnt>& out) {
  const double tolerance = std::min(edgeTolerance, kOnPlane);
  const BRepAdaptor_Curve c(edge);
  const double t0 = c.FirstParameter(), t1 = c.LastParameter();
  const auto f = [&](double t) { return n.XYZ().Dot(c.Value(t).XYZ()) - d; };
  const double f0 = f(t0), f1 = f(t1);
  if (std::abs(f0) <= tolerance || std::abs(f1) <= tolerance) return false;
  const GeomAbs_CurveType type = c.GetType();
  if (type == GeomAbs_Line) {
    if ((f0 < 0) != (f1 < 0)) out.push_back(c.Value(t0 + (t1 - t0) * f0 / (f0 - f1)));
    return true;
  }
  if (type == GeomAbs_Circle || type == GeomAbs_Ellipse) {
    // f(t) = c0 + a cos t + b sin t = c0 + r cos(t - phi).
    const gp_Ax2 ax = type == GeomAbs_Circle ? c.Circle().Position() : c.Ellipse().Position();
    const double r1 = type == GeomAbs_Circle ? c.Circle().Radius() : c.Ellipse().MajorRadius();
    const double r2 = type == GeomAbs_Circle ? r1 : c.Ellipse().MinorRadius();
    const double c0 = n.XYZ().Dot(ax.Location().XYZ()) - d;
    const double a = r1 * n.Dot(ax.XDirection()), b = r2 * n.Dot(ax.YDirection());
    const double r = std::hypot(a, b);
    if (std::abs(r - std::abs(c0)) <= tolerance) return false;  // tangent
    if (r < std::abs(c0)) return true;
    const double phi = std::atan2(b, a), delta = std::acos(-c0 / r);
    for (const double root : {phi - delta, phi + delta}) {
      const double t = ElCLib::InPeriod(root, t0, t0 + kTwoPi);
      if (t > t0 && t < t1) out.push_back(c.Value(t));
    }
    return true;
  }
  // Any other curve: sign changes between samples, found by bisection. A sample on the
  // plane is a touch, or a crossing at it: where the next sample lies across the plane from
  // the one before, the two steps are one, with one crossing, as between any two samples;
  // else unsure (a touch, or two crossings). occ/Motor-c.brep in its auto frame: a B-spline
  // edge's sample 48 nm from one U plane of 62 sent that plane to the section (20 ms).
  const int samples = type == GeomAbs_BSplineCurve ? std::clamp(4 * c.NbPoles(), 64, 1024) : 64;
  // Sample i: its parameter, and the signed distance there.
  const auto sample = [&](int i) -> std::pair<double, double> {
    if (i == samples) return {t1, f1};
    const double t = t0 + (t1 - t0) * i / samples;
    return {t, f(t)};
  };
  double ta = t0, fa = f0;
  for (int i = 1; i <= samples; ++i) {
    auto [tb, fb] = sample(i);
    if (std::abs(fb) <= tolerance) {  // never the last: f1 is not on the plane
      std::tie(tb, fb) = sample(++i);
      if (std::abs(fb) <= tolerance || (fa < 0) == (fb < 0)) return false;
    }
    if ((fa < 0) != (fb < 0)) {
      double lo = ta, hi = tb, flo = fa;
      for (int k = 0; k < 100 && hi - lo > 1e-15 * (std::abs(lo) + 1); ++k) {
        const double mid = (lo + hi) / 2, fm = f(mid);
        if ((fm < 0) == (flo < 0))
          lo = mid, flo = fm;
        else
          hi = mid;
      }
      out.push_back(c.Value((lo + hi) / 2));
    }
    ta = tb, fa = fb;
  }
  return true;
}

// A vertex at a crossing of a solid's edge, or at a free end of a curve; `own` when this
// route made it, false for a vertex of OCCT's section, which may be the solid's own.
struct End {
  double t;
  TopoDS_Vertex vertex;
  bool own = true;
};

TopoDS_Edge piece(const SectionCurve& c, const End& a, double tb, const End& b) {
  BRep_Builder builder;
  // The vertices cover where the curve meets them: a crossing lies on the solid's edge,
  // which is only within its tolerance of the face. Only the route's own vertices are
  // widened: the solid's are shared with every thread slicing it (joinAtCrossings refuses
  // a piece whose OCCT vertex does not cover its end).
  for (const auto& [t, v, own] : {std::tuple{a.t, a.vertex, a.own}, std::tuple{tb, b.vertex, b.own}}) {
    const double gap = c.curve->Value(t).Distance(BRep_Tool::Pnt(v));
    if (own && gap > BRep_Tool::Tolerance(v)) builder.UpdateVertex(v, gap * 1.01);
  }
  TopoDS_Edge edge;
  builder.MakeEdge(edge, c.curve, std::max(c.tolerance, Precision::Confusion()));
  builder.Add(edge, a.vertex.Oriented(TopAbs_FORWARD));
  builder.Add(edge, b.vertex.Oriented(TopAbs_REVERSED));
  builder.Range(edge, a.t, tb);
  return edge;
}

// Whether this route solves the sections of the face by planes normal to `n`: planes,
// cylinders, cones, spheres, and tori across or along the planes. A face of any other kind,
// a torus aslant too, is cut by OCCT alone (cutAlone).
bool solvedBy(const BRepAdaptor_Surface& s, const gp_Dir& n) {
  const GeomAbs_SurfaceType type = s.GetType();
  if (type == GeomAbs_Torus) {
    // IntAna solves a torus cut across only when its tube does not reach the axis (R > r).
    const gp_Torus torus = s.Torus();
    const gp_Dir axis = torus.Axis().Direction();
    return (axis.IsParallel(n, Precision::Angular()) && torus.MajorRadius() > torus.MinorRadius()) ||
           axis.IsNormal(n, Precision::Angular());
  }
  return type == GeomAbs_Plane || type == GeomAbs_Cylinder || type == GeomAbs_Cone || type == GeomAbs_Sphere;
}

TopoDS_Vertex vertexAt(const gp_Pnt& p, double tolerance) {
  TopoDS_Vertex v;
  BRep_Builder().MakeVertex(v, p, tolerance);
  return v;
}

// A crossing of a solid's edge by the plane: where, its vertex, the edge's tolerance.
struct Crossing {
  gp_Pnt point;
  TopoDS_Vertex vertex;
  double tolerance;
};

// The sections of one face this route does not solve (a B-spline, a surface of revolution,
// a torus cut aslant) by the planes at `d` (along `n`): BRepAlgoAPI_Section of that face
// alone with a square on each plane, one Boolean for all of them; per plane its edges,
// nullopt for every plane where OCCT reports a problem or an edge lies off its plane. The
// section of the whole solid did the same intersections, after setting up every other face
// and edge of the solid against every plane of its batch: 60-70 ms a plane on
// occ/MODERN_Sink_1.brep. One Boolean a face and plane set the face up again for each plane
// (occ/CrankArm.brep's exact patches 2.33 s, 1.87 with one for all).
std::vector<std::optional<std::vector<FaceByFace::AloneEdge>>> cutAlone(const TopoDS_Face& face,
                                                                        const Bnd_Box& box, const gp_Dir& n,
                                                                        const gp_Dir& x,
                                                                        const std::vector<double>& d) {
  std::vector<std::optional<std::vector<FaceByFace::AloneEdge>>> out(d.size());
  const gp_XYZ centre = (box.CornerMin().XYZ() + box.CornerMax().XYZ()) / 2;
  const double half = box.CornerMin().Distance(box.CornerMax()) + 1;
  TopoDS_Compound squares;  // on each plane, centred on the face's box
  BRep_Builder builder;
  builder.MakeCompound(squares);
  for (const double at : d) {
    const gp_Pnt origin(centre - n.XYZ() * (n.XYZ().Dot(centre) - at));
    builder.Add(squares,
                BRepBuilderAPI_MakeFace(gp_Pln(gp_Ax3(origin, n, x)), -half, half, -half, half).Face());
  }
  const TopoDS_Shape section = sectionCurves(face, squares, true);
  if (section.IsNull()) return out;
  const std::vector<std::optional<std::vector<TopoDS_Edge>>> byPlane = edgesByPlane(section, n, d);
  for (size_t k = 0; k < d.size(); ++k) {
    if (!byPlane[k]) continue;
    out[k].emplace();
    for (const TopoDS_Edge& edge : *byPlane[k]) {
      FaceByFace::AloneEdge e{edge, {}, {}};
      TopExp::Vertices(e.edge, e.first, e.last);  // FORWARD at the first parameter
      if (e.first.IsNull() || e.last.IsNull()) return decltype(out)(d.size());
      out[k]->push_back(e);
    }
  }
  return out;
}

// The edges of a face cut alone by a plane, appended to `out`, each end at one of
// `crossings` (those of the face's edges) given that crossing's vertex, which the pieces of
// the neighbouring faces end at too, so that they chain by shared vertices; false where
// unsure, and then nothing is appended or changed. An end at no crossing must be shared by
// another edge of the face's section (a curve split inside the face, a closed curve's own
// vertex); an end near two is unsure. And every crossing must end an edge: the face's
// section meets its boundary there. The trace misses a contour that stays within one cell
// of its grid (occ/Top.brep, directions auto: a B-spline face cut in a sliver 0.43 mm long
// at its border, at one of 107 planes, which then took the solid's section and its Common,
// 0.4 s).
bool joinAtCrossings(const std::vector<FaceByFace::AloneEdge>& edges, const std::vector<Crossing>& crossings,
                     Handle(TopTools_HSequenceOfShape) out) {
  std::map<const TopoDS_TShape*, int> uses;  // how many ends each vertex is
  for (const FaceByFace::AloneEdge& e : edges) ++uses[e.first.TShape().get()], ++uses[e.last.TShape().get()];
  // The one crossing within the tolerances of `v`: its index, -1 for none, nullopt for two.
  const auto crossingAt = [&](const TopoDS_Vertex& v) -> std::optional<int> {
    const gp_Pnt p = BRep_Tool::Pnt(v);
    int found = -1;
    for (size_t i = 0; i < crossings.size(); ++i)
      if (p.Distance(crossings[i].point) <= 2 * (crossings[i].tolerance + BRep_Tool::Tolerance(v)) + 1e-5) {
        if (found >= 0) return std::nullopt;
        found = static_cast<int>(i);
      }
    return found;
  };
  std::vector<bool> ended(crossings.size(), false);
  std::vector<std::pair<SectionCurve, std::array<End, 2>>> pieces;
  for (const FaceByFace::AloneEdge& e : edges) {
    double first = 0, last = 0;
    const Handle(Geom_Curve) curve = BRep_Tool::Curve(e.edge, first, last);
    if (curve.IsNull()) return false;
    std::array<End, 2> at = {End{first, e.first, false}, End{last, e.last, false}};
    for (End& end : at) {
      const std::optional<int> crossing = crossingAt(end.vertex);
      if (!crossing) return false;
      if (*crossing >= 0)
        end.vertex = crossings[*crossing].vertex, end.own = true, ended[*crossing] = true;
      else if (uses[end.vertex.TShape().get()] < 2)
        return false;  // an end on the face's boundary at no crossing found
      else if (curve->Value(end.t).Distance(BRep_Tool::Pnt(end.vertex)) > BRep_Tool::Tolerance(end.vertex))
        return false;  // OCCT's vertex does not cover the end of its own edge
    }
    SectionCurve c;
    c.curve = curve, c.first = first, c.last = last, c.tolerance = BRep_Tool::Tolerance(e.edge);
    pieces.push_back({c, at});
  }
  if (std::find(ended.begin(), ended.end(), false) != ended.end()) return false;
  for (const auto& [c, at] : pieces) out->Append(piece(c, at[0], c.last, at[1]));
  return true;
}

}  // namespace

TopoDS_Shape sectionCurves(const TopoDS_Shape& shape, const TopoDS_Shape& cutters, bool strict) {
  BRepAlgoAPI_Section section;
  TopTools_ListOfShape arguments, tools;
  arguments.Append(shape);
  tools.Append(cutters);
  section.SetArguments(arguments);
  section.SetTools(tools);
  // Curves only: the faces are made from them on the plane. Measured on 128 planes of
  // occ/Pump_TopCover.brep (B-spline faces), one core: the walking lines approximated with
  // their curves on the solid's faces 8.3 s, in 3D alone 40 s, not approximated 36 s (and
  // polylines of ~1000 points that made the slot Booleans 60x slower on screw.step). On the
  // cutters no curves are needed.
  section.Approximation(Standard_True);
  section.ComputePCurveOn1(Standard_True);
  section.ComputePCurveOn2(Standard_False);
  section.SetNonDestructive(Standard_True);
  section.SetRunParallel(Standard_False);
  section.Build();
  if (!section.IsDone() || section.HasErrors() || (strict && section.HasWarnings())) return {};
  return section.Shape();
}

std::vector<std::optional<std::vector<TopoDS_Edge>>> edgesByPlane(const TopoDS_Shape& section,
                                                                  const gp_Dir& n,
                                                                  const std::vector<double>& d) {
  std::vector<std::optional<std::vector<TopoDS_Edge>>> out(d.size());
  if (d.empty()) return out;
  for (auto& edges : out) edges.emplace();
  std::vector<bool> unsure(d.size(), false);
  for (TopExp_Explorer it(section, TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
    double first = 0, last = 0;
    const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
    if (curve.IsNull()) return decltype(out)(d.size());
    const double p = n.XYZ().Dot(curve->Value((first + last) / 2).XYZ());
    size_t nearest = 0;
    for (size_t k = 1; k < d.size(); ++k)
      if (std::abs(d[k] - p) < std::abs(d[nearest] - p)) nearest = k;
    const auto off = [&](double t) { return std::abs(n.XYZ().Dot(curve->Value(t).XYZ()) - d[nearest]); };
    if (std::abs(d[nearest] - p) > kOffPlane || off(first) > kOffPlane || off(last) > kOffPlane)
      for (size_t k = 0; k < d.size(); ++k)
        if (k == nearest || std::abs(d[k] - p) <= BRep_Tool::Tolerance(edge) + kOffPlane) unsure[k] = true;
    out[nearest]->push_back(edge);
  }
  for (size_t k = 0; k < d.size(); ++k)
    if (unsure[k]) out[k].reset();
  return out;
}

FaceByFace::FaceByFace(const TopoDS_Shape& solid, const gp_Dir& normal) : normal_(normal) {
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(solid, TopAbs_EDGE, edges);
  for (Standard_Integer i = 1; i <= edges.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(edges(i));
    Bnd_Box box;
    if (!BRep_Tool::Degenerated(e)) BRepBndLib::Add(e, box);
    const auto [lo, hi] = box.IsVoid() ? std::pair{1.0, 0.0} : along(box, normal);  // empty: never crossed
    edges_.push_back({e, lo, hi, std::max(BRep_Tool::Tolerance(e), Precision::Confusion())});
  }
  // What the classifier reads: of a plane, a copy with its edges' 2D curves stored, made
  // once (withPlaneCurves); else the face itself.
  std::vector<TopoDS_Face> classified;
  for (TopExp_Explorer it(solid, TopAbs_FACE); it.More(); it.Next()) {
    Face f;
    f.face = TopoDS::Face(it.Current());
    BRepBndLib::Add(f.face, f.box);
    std::tie(f.lo, f.hi) = along(f.box, normal);
    const BRepAdaptor_Surface surface(f.face, Standard_False);
    f.solved = solvedBy(surface, normal);
    classified.push_back(
        f.solved && surface.GetType() == GeomAbs_Plane ? TopoDS::Face(withPlaneCurves(f.face)) : f.face);
    for (TopExp_Explorer e(f.face, TopAbs_EDGE); e.More(); e.Next()) {
      const int index = edges.FindIndex(e.Current()) - 1;
      if (std::find(f.edges.begin(), f.edges.end(), index) == f.edges.end()) f.edges.push_back(index);
    }
    faces_.push_back(std::move(f));
  }
  parallelFor(faces_.size(), [&](size_t i) {
    Face& f = faces_[i];
    if (f.solved) {
      f.inside = std::make_shared<const FaceInside>(f.face, classified[i]);
      return;
    }
    try {
      f.traced = std::make_shared<const TracedFace>(f.face, normal);
      if (f.traced->empty()) f.traced.reset();
    } catch (const Standard_Failure&) {
      f.traced.reset();  // OCCT's walk cuts it
    }
  });
}

std::vector<Handle(TopTools_HSequenceOfShape)> FaceByFace::edges(const std::vector<gp_Pln>& planes) const {
  std::vector<double> d;
  for (const gp_Pln& plane : planes) d.push_back(normal_.XYZ().Dot(plane.Location().XYZ()));
  const gp_Dir x = planes.empty() ? gp_Dir() : planes.front().XAxis().Direction();
  // The faces this route does not solve, each cut by the planes that reach it at once.
  Alone alone(faces_.size());
  for (size_t i = 0; i < faces_.size(); ++i) {
    const Face& f = faces_[i];
    if (f.solved) continue;
    std::vector<double> reach;
    for (const double at : d)
      if (at >= f.lo && at <= f.hi) reach.push_back(at);
    if (reach.empty()) continue;
    const auto cut = [&](const std::vector<double>& at) {
      try {
        return cutAlone(f.face, f.box, normal_, x, at);
      } catch (const Standard_Failure&) {
        return std::vector<std::optional<std::vector<AloneEdge>>>(at.size());  // each plane unsure
      }
    };
    // Traced where the trace is sure, by OCCT at the planes left.
    std::vector<std::optional<std::vector<AloneEdge>>> cuts(reach.size());
    std::vector<size_t> left;
    for (size_t r = 0; r < reach.size(); ++r) {
      if (f.traced) cuts[r] = f.traced->cut(reach[r]);
      if (!cuts[r]) left.push_back(r);
    }
    std::vector<double> at;
    for (const size_t r : left) at.push_back(reach[r]);
    std::vector<std::optional<std::vector<AloneEdge>>> byOcct = at.empty() ? decltype(cuts)() : cut(at);
    // OCCT's doubt about one plane (a warning: a too small edge) is about all of the
    // Boolean's: where it doubts, each plane is cut alone again. (One plane unsure of its
    // own edges, cutAlone's check, leaves the others as they are.)
    if (at.size() > 1 &&
        std::none_of(byOcct.begin(), byOcct.end(), [](const auto& c) { return c.has_value(); }))
      for (size_t r = 0; r < at.size(); ++r) byOcct[r] = std::move(cut({at[r]}).front());
    for (size_t k = 0; k < left.size(); ++k) cuts[left[k]] = std::move(byOcct[k]);
    alone[i].resize(d.size());
    for (size_t k = 0, r = 0; k < d.size(); ++k)
      if (d[k] >= f.lo && d[k] <= f.hi) alone[i][k] = std::move(cuts[r++]);
  }
  std::vector<Handle(TopTools_HSequenceOfShape)> out;
  for (size_t k = 0; k < planes.size(); ++k) {
    try {
      out.push_back(planeEdges(planes[k], d[k], alone, k));
    } catch (const Standard_Failure&) {
      out.push_back(nullptr);
    }
  }
  return out;
}

Handle(TopTools_HSequenceOfShape) FaceByFace::planeEdges(const gp_Pln& plane, double d, const Alone& alone,
                                                         size_t k) const {
  // Each edge's crossings and their vertices, shared by the faces on either side.
  std::vector<std::vector<std::pair<gp_Pnt, TopoDS_Vertex>>> crossed(edges_.size());
  for (size_t i = 0; i < edges_.size(); ++i) {
    const Edge& e = edges_[i];
    if (d < e.lo || d > e.hi) continue;
    std::vector<gp_Pnt> points;
    if (!crossings(e.edge, e.tolerance, normal_, d, points)) return nullptr;
    for (const gp_Pnt& p : points) crossed[i].emplace_back(p, vertexAt(p, e.tolerance));
  }
  Handle(TopTools_HSequenceOfShape) out = new TopTools_HSequenceOfShape;
  for (size_t i = 0; i < faces_.size(); ++i) {
    const Face& f = faces_[i];
    if (d < f.lo || d > f.hi) continue;
    if (!f.solved) {
      if (!alone[i][k]) return nullptr;
      std::vector<Crossing> at;
      for (const int e : f.edges)
        for (const auto& [p, vertex] : crossed[e]) at.push_back({p, vertex, edges_[e].tolerance});
      if (joinAtCrossings(*alone[i][k], at, out)) continue;
      // Where the trace was sure and wrong, OCCT cuts this face alone by this plane.
      if (!f.traced) return nullptr;  // OCCT's cut already, or nothing to trace
      const std::optional<std::vector<AloneEdge>> cut =
          cutAlone(f.face, f.box, normal_, plane.XAxis().Direction(), {d}).front();
      if (!cut || !joinAtCrossings(*cut, at, out)) return nullptr;
      continue;
    }
    const BRepAdaptor_Surface s(f.face, Standard_False);
    std::vector<SectionCurve> curves;
    if (!planeSurfaceCurves(s, plane, f.box, curves)) return nullptr;
    // Each crossing of the face's edges to every curve it lies on: within the tolerances,
    // and not ten times further than the nearest (and 10 nm). A loose edge's tolerance
    // reaches other curves too: occ/MODERN_Sink_1.brep's edges claim 3 mm, and a rim's
    // crossing on one of a cylinder's two lines, 1.75 mm from the other, ended a piece of
    // both at one point (three V planes of 52 went to the section, 0.3 s of 1.0).
    std::vector<std::vector<End>> ends(curves.size());
    const double faceTolerance = BRep_Tool::Tolerance(f.face);
    for (const int e : f.edges)
      for (const auto& [p, vertex] : crossed[e]) {
        bool on = false;
        // 10 nm more than the tolerances say: edges of real files stray from their faces
        // by up to 1 nm where both claim 0.1 nm (occ/Bottom.brep).
        std::vector<double> budget;
        for (const SectionCurve& c : curves)
          budget.push_back(2 * (edges_[e].tolerance + faceTolerance + c.tolerance) + 1e-5);
        std::vector<std::pair<double, double>> feet;  // (t, distance) on each curve
        double nearest = HUGE_VAL;
        for (const SectionCurve& c : curves) {
          feet.push_back(projectOnSection(c, p));
          nearest = std::min(nearest, feet.back().second);
        }
        for (size_t k = 0; k < curves.size(); ++k) {
          const auto [t, distance] = feet[k];
          if (distance <= budget[k] && distance <= std::max(10 * nearest, nearest + 1e-5))
            ends[k].push_back({t, vertex}), on = true;
        }
        if (on) continue;
        const std::optional<std::pair<size_t, double>> grazed = grazedFoot(s, curves, budget, p, normal_);
        if (!grazed) return nullptr;
        // The vertex's tolerance reaches the curve's end, as the pieces' ends must.
        const auto [k, t] = *grazed;
        const double gap = curves[k].curve->Value(t).Distance(p);
        if (gap > BRep_Tool::Tolerance(vertex)) BRep_Builder().UpdateVertex(vertex, gap * (1 + 1e-6));
        ends[k].push_back({t, vertex});
      }
    for (size_t k = 0; k < curves.size(); ++k) {
      const SectionCurve& c = curves[k];
      std::vector<End>& cuts = ends[k];
      const double period = c.last - c.first;
      if (c.periodic)
        for (End& cut : cuts) cut.t = ElCLib::InPeriod(cut.t, c.first, c.last);
      std::sort(cuts.begin(), cuts.end(), [](const End& a, const End& b) { return a.t < b.t; });
      if (c.periodic && cuts.empty()) {
        if (f.inside->classify(s, c.curve->Value(c.first + period / 2)) == TopAbs_IN)
          out->Append(BRepBuilderAPI_MakeEdge(c.curve, c.first, c.last).Edge());
        continue;
      }
      // The stretches between consecutive crossings; an open curve (a line, a cone's
      // parabola or hyperbola) runs past the face at both ends, where its ends are.
      std::vector<End> bounds = cuts;
      if (!c.periodic) {
        bounds.insert(bounds.begin(), {c.first, vertexAt(c.curve->Value(c.first), Precision::Confusion())});
        bounds.push_back({c.last, vertexAt(c.curve->Value(c.last), Precision::Confusion())});
      }
      const size_t stretches = c.periodic ? bounds.size() : bounds.size() - 1;
      for (size_t i = 0; i < stretches; ++i) {
        const End& a = bounds[i];
        const End& b = bounds[(i + 1) % bounds.size()];
        const double tb = i + 1 == bounds.size() ? b.t + period : b.t;
        if (tb - a.t <= 1e-9 * (std::abs(period) + 1)) return nullptr;  // two crossings at one point
        const TopAbs_State state = f.inside->classify(s, c.curve->Value((a.t + tb) / 2));
        if (state == TopAbs_ON) return nullptr;
        if (state != TopAbs_IN) continue;
        if (tb > c.last && c.curve->IsKind(STANDARD_TYPE(Geom_BSplineCurve))) {
          // A torus's loop: an edge past the end of a periodic B-spline's parameters made
          // the exact patches' Booleans leave a patch in six faces (a torus cut along its
          // axis), so the piece is split where the loop closes. Conics keep one edge.
          const End seam{c.first, vertexAt(c.curve->Value(c.first), Precision::Confusion())};
          out->Append(piece(c, a, c.last, End{c.last, seam.vertex}));
          out->Append(piece(c, seam, b.t, b));
        } else {
          out->Append(piece(c, a, tb, b));
        }
      }
    }
  }
  return out;
}

}  // namespace sliceform
