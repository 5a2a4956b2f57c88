// SPDX-License-Identifier: LGPL-2.1-or-later
#include "exact/patch_faces.hpp"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepGProp.hxx>
#include <BRepOffsetAPI_MakeOffset.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Ax3.hxx>
#include <gp_Circ.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

#include "exact/rebuilt_faces.hpp"
#include "geometry/simplify.hpp"
#include "slicing/brep_slicer.hpp"
#include "support/error.hpp"
#include "support/occt_guard.hpp"
#include "support/parallel.hpp"
#include "support/per_family.hpp"

namespace sliceform {
namespace {

gp_Pnt point(const SliceFrame& frame, Vec2 q, double position) {
  const Vec3 p = frame.to3d(q, position);
  return {p.x, p.y, p.z};
}

gp_Pln plane(const SliceFrame& frame, double position) {
  const Vec3 o = frame.normal * position;
  return gp_Pln(gp_Ax3(gp_Pnt(o.x, o.y, o.z), gp_Dir(frame.normal.x, frame.normal.y, frame.normal.z),
                       gp_Dir(frame.xAxis.x, frame.xAxis.y, frame.xAxis.z)));
}

TopoDS_Wire polygonWire(const Region2d::Loop& loop, const SliceFrame& frame, double position) {
  BRepBuilderAPI_MakePolygon polygon;
  for (const Vec2& q : loop) polygon.Add(point(frame, q, position));
  polygon.Close();
  if (!polygon.IsDone()) throw Error(ErrorKind::Geometry, "cannot build a polygon wire");
  return polygon.Wire();
}

TopoDS_Compound compound(const std::vector<TopoDS_Shape>& shapes) {
  TopoDS_Compound c;
  BRep_Builder builder;
  builder.MakeCompound(c);
  for (const TopoDS_Shape& s : shapes) builder.Add(c, s);
  return c;
}

std::vector<TopoDS_Shape> faces(const TopoDS_Shape& shape) {
  std::vector<TopoDS_Shape> out;
  for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) out.push_back(it.Current());
  return out;
}

double area(const TopoDS_Shape& shape) {
  GProp_GProps props;
  BRepGProp::SurfaceProperties(shape, props);
  return props.Mass();
}

// A Boolean of planar faces (fuse when `cutting` is false), then coplanar pieces merged so
// that one patch is one face again and arcs split by the Boolean are whole again.
TopoDS_Shape boolean(const std::vector<TopoDS_Shape>& arguments, const std::vector<TopoDS_Shape>& tools,
                     bool cutting) {
  TopTools_ListOfShape args, tls;
  for (const TopoDS_Shape& s : arguments) args.Append(s);
  for (const TopoDS_Shape& s : tools) tls.Append(s);
  auto run = [&](BRepAlgoAPI_BooleanOperation& op) {
    op.SetArguments(args);
    op.SetTools(tls);
    op.SetNonDestructive(Standard_True);  // slice faces are shared between patches
    // On OCCT's threads too, as the sections' Common: a cylinder's fuse can be the stage's
    // longest task, run on one core while the other waited (occ/Motor-c.brep: one fuse of
    // 5 slices, 660 ms of the stage's 923; 5.55 -> 5.20 s end to end). The same faces.
    op.SetRunParallel(Standard_True);
    // Sections of neighbouring slices have nearly coincident, nearly tangent edges. Exact
    // Booleans then left overlapping pieces that no longer unify (occ/Ball.brep: 8 faces
    // fused into 52, 2 % too much area); a fuzzy value of 10 nm merges them into one face.
    op.SetFuzzyValue(1e-5);
    op.Build();
    if (!op.IsDone() || op.HasErrors()) {
      std::ostringstream report;
      op.DumpErrors(report);
      throw Error(ErrorKind::Geometry,
                  std::string(cutting ? "cutting slots" : "fusing sections") + " failed: " + report.str());
    }
    ShapeUpgrade_UnifySameDomain unify(op.Shape(), Standard_True, Standard_True, Standard_False);
    unify.Build();
    return unify.Shape();
  };
  if (cutting) {
    BRepAlgoAPI_Cut op;
    return run(op);
  }
  BRepAlgoAPI_Fuse op;
  return run(op);
}

// The faces below are made from loops that run counter-clockwise about the plane's normal
// (the frame's x, y and normal are right-handed, and so are the plane's axes), so OCCT is
// not asked to check that the wire bounds a finite face (BRepLib_MakeFace::CheckInside
// made a classifier of each face for that: 15 % of the exact patches on Bottom.brep).

// The slot strips of one patch as faces on its plane.
std::vector<TopoDS_Shape> slotFaces(const SlotShapes& shapes, const SliceFrame& frame, double position) {
  std::vector<TopoDS_Shape> out;
  const gp_Pln pln = plane(frame, position);
  for (const Box2& b : shapes.rectangles) {
    const Region2d::Loop loop = Region2d::rectangle(b.min.x, b.min.y, b.max.x, b.max.y);
    out.push_back(BRepBuilderAPI_MakeFace(pln, polygonWire(loop, frame, position), Standard_False).Face());
  }
  for (const Disc& d : shapes.discs) {
    gp_Ax2 axis(point(frame, d.centre, position), pln.Axis().Direction(), pln.XAxis().Direction());
    const TopoDS_Edge edge = BRepBuilderAPI_MakeEdge(gp_Circ(axis, d.radius)).Edge();
    out.push_back(BRepBuilderAPI_MakeFace(pln, BRepBuilderAPI_MakeWire(edge).Wire(), Standard_False).Face());
  }
  return out;
}

// What lies near a cylinder's section: its own pieces of a slice, which may hold pieces of
// other parts of the model.
Region2d nearCylinder(const Cylinder& cylinder, double meshDeflection) {
  return cylinder.section.offset(std::max(4 * meshDeflection, 0.05));
}

// Whether at least half of `piece` lies in `near` (whose bounds are `nearBox`). Most of a
// slice's pieces lie far from a given cylinder (occ/Bottom.brep: 335 of 709 with boxes
// apart): those need no Boolean.
bool mostlyNear(const Region2d& piece, const Region2d& near, const Box2& nearBox) {
  const double area = piece.area();
  if (area > 0 && apart(piece.bounds(), nearBox, 0)) return false;
  return piece.intersect(near).area() >= 0.5 * area;
}

// The slices of a cylinder whose sections add to its union, chosen on the search's polygon
// slices before any exact section is cut. They lie within the mesh deflection of the exact
// sections, and most of a cylinder's slices lie inside another: on screw.step every
// cylinder's union is one of its sections, and 244 exact sections were cut for the 24 fused.
std::vector<int> slicesAddingToUnion(const Cylinder& cylinder, const SliceSet& set, double meshDeflection) {
  const Region2d near = nearCylinder(cylinder, meshDeflection);
  const Box2 nearBox = near.bounds();
  std::vector<int> slices;
  std::vector<Region2d> polygons;
  for (int k = cylinder.firstSlice; k <= cylinder.lastSlice; ++k) {
    std::vector<Region2d> own;
    for (const Region2d& piece : set.slices[k].region.components())
      if (mostlyNear(piece, near, nearBox)) own.push_back(piece);
    if (own.empty()) continue;
    slices.push_back(k);
    polygons.push_back(Region2d::uniteAll(own));
  }
  std::vector<int> out;
  for (const size_t i : sectionsAddingToUnion(polygons, 2 * exactDeflection(meshDeflection)))
    out.push_back(slices[i]);
  std::sort(out.begin(), out.end());
  return out;
}

// The exact cross-section of one cylinder on the plane at position 0 of its frame, from the
// exact sections at `chosen` slices.
TopoDS_Shape exactSection(const Cylinder& cylinder, const std::vector<int>& chosen,
                          const std::map<int, ExactSlice>& slices, const SliceFrame& frame,
                          double meshDeflection) {
  const double deflection = exactDeflection(meshDeflection);
  const Region2d near = nearCylinder(cylinder, meshDeflection);
  const Box2 nearBox = near.bounds();
  std::vector<TopoDS_Shape> candidates;
  std::vector<Region2d> polygons;
  for (const int k : chosen) {
    const auto slice = slices.find(k);
    if (slice == slices.end()) throw Error(ErrorKind::Geometry, "an exact section was not cut");
    const ExactSlice& s = slice->second;
    if (s.faces.IsNull()) continue;
    gp_Trsf onto;
    onto.SetTranslation(
        gp_Vec(-frame.normal.x * s.position, -frame.normal.y * s.position, -frame.normal.z * s.position));
    for (const TopoDS_Shape& f : faces(s.faces)) {
      Region2d poly = polygoniseFaces(f, frame, deflection);
      if (!mostlyNear(poly, near, nearBox)) continue;
      candidates.push_back(f.Moved(TopLoc_Location(onto)));
      polygons.push_back(std::move(poly));
    }
  }
  std::vector<TopoDS_Shape> own;
  for (const size_t k : sectionsAddingToUnion(polygons, 2 * deflection)) own.push_back(candidates[k]);
  // Rebuilt from the exact edges along the union of their polygons; the Boolean fuse where
  // that is unsure (exact/rebuilt_faces.hpp).
  TopoDS_Shape fused = own.size() == 1 ? own.front() : TopoDS_Shape();
  if (own.size() > 1)
    fused = rebuiltFaces(
        own, [](const std::vector<Region2d>& p) { return Region2d::uniteAll(p); }, frame, 0, deflection);
  if (fused.IsNull() && own.size() > 1) fused = boolean({own.front()}, {own.begin() + 1, own.end()}, false);
  // Material of the polygon section the exact slices lack (merged-in branches): keep it, as
  // polygons, so every hinge found on the polygons is on paper.
  const double opening = std::max(4 * meshDeflection, 0.05);
  Region2d missing = cylinder.section;
  if (!fused.IsNull()) missing = missing.subtract(polygoniseFaces(fused, frame, deflection));
  missing = missing.offset(-opening).offset(2 * opening).intersect(cylinder.section.offset(opening));
  if (!missing.empty()) {
    const TopoDS_Shape extra = facesFromRegion(missing, frame, 0);
    fused = fused.IsNull() ? extra : boolean({fused}, faces(extra), false);
  }
  return fused;
}

}  // namespace

std::vector<size_t> sectionsAddingToUnion(const std::vector<Region2d>& sections, double tolerance) {
  std::vector<size_t> order(sections.size());
  std::vector<double> area(sections.size());
  for (size_t k = 0; k < sections.size(); ++k) order[k] = k, area[k] = sections[k].area();
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return area[a] > area[b]; });
  std::vector<size_t> kept;
  Region2d taken, reach;
  for (const size_t k : order) {
    if (!kept.empty() && sections[k].subtract(reach).area() <= tolerance * tolerance) continue;
    kept.push_back(k);
    taken = taken.unite(sections[k]);
    reach = taken.offset(tolerance);
  }
  return kept;
}

namespace {

// Whether two of the loops share a vertex. Clipper's output is not strictly simple: a hole
// may touch the outer loop or another hole at a point (diplodocus.off in 3 mm plywood: three
// holes 15-20 µm wide touching the outer loop), and a face made of such wires fails
// BRepCheck ("intersecting wires").
bool touching(const std::vector<Region2d::Loop>& loops) {
  std::map<std::pair<double, double>, size_t> owner;
  for (size_t k = 0; k < loops.size(); ++k)
    for (const Vec2& p : loops[k]) {
      const auto [at, added] = owner.emplace(std::pair{p.x, p.y}, k);
      if (!added && at->second != k) return true;
    }
  return false;
}

}  // namespace

TopoDS_Shape facesFromRegion(const Region2d& region, const SliceFrame& frame, double position) {
  std::vector<TopoDS_Shape> out;
  const gp_Pln pln = plane(frame, position);
  for (const Region2d& piece : region.components()) {
    std::vector<Region2d::Loop> loops = piece.loops();  // outer (counter-clockwise) first
    std::stable_partition(loops.begin(), loops.end(),
                          [](const Region2d::Loop& l) { return Region2d::signedArea(l) > 0; });
    if (touching(loops)) {
      // The outer loop's face less the holes' by OCCT's Boolean, which shares the vertex
      // where they touch: a valid face, the same polygon.
      std::vector<TopoDS_Shape> holes;
      for (size_t k = 1; k < loops.size(); ++k) {
        const Region2d::Loop ccw(loops[k].rbegin(), loops[k].rend());
        holes.push_back(
            BRepBuilderAPI_MakeFace(pln, polygonWire(ccw, frame, position), Standard_False).Face());
      }
      const TopoDS_Shape outer =
          BRepBuilderAPI_MakeFace(pln, polygonWire(loops.front(), frame, position), Standard_False).Face();
      for (const TopoDS_Shape& f : faces(boolean({outer}, holes, true))) out.push_back(f);
      continue;
    }
    BRepBuilderAPI_MakeFace face(pln, polygonWire(loops.front(), frame, position), Standard_False);
    // Holes run clockwise in the frame, whose normal is the plane's: OCCT's hole sense.
    for (size_t k = 1; k < loops.size(); ++k) face.Add(polygonWire(loops[k], frame, position));
    if (!face.IsDone()) throw Error(ErrorKind::Geometry, "cannot build a patch face from its polygon");
    out.push_back(face.Face());
  }
  return out.size() == 1 ? out.front() : compound(out);
}

std::vector<PatchFace> exactPatches(const Model& model, const Arrangement& a, const Realization& r,
                                    const Deadline& deadline, ExactSections* known) {
  const Scaffold& scaffold = a.scaffold;
  std::vector<PatchFace> out(scaffold.patches.size());
  const bool exact = model.kind == SourceKind::Brep && !model.shape.IsNull();
  ExactSections none;
  std::map<std::pair<int, int>, TopoDS_Shape>& sections = (known ? *known : none).byCylinder;
  // Exact sections of the cylinders with patches and none known, each needed slice cut once.
  PerFamily<std::map<int, ExactSlice>> exactSlices;
  std::vector<std::pair<int, int>> keys;  // (family, cylinder) of every patch
  for (const ScaffoldPatch& p : scaffold.patches) keys.push_back({familyIndex(p.family), p.cylinder});
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  const auto taken =
      std::stable_partition(keys.begin(), keys.end(), [&](const auto& k) { return !sections.count(k); });
  if (known) known->taken = static_cast<int>(keys.end() - taken);
  keys.erase(taken, keys.end());
  std::vector<std::vector<int>> chosen(keys.size());
  if (exact)
    parallelFor(keys.size(), [&](size_t i) {
      const Family f = familyAt(keys[i].first);
      chosen[i] = slicesAddingToUnion(a.cylinders(f)[keys[i].second], a.slices(f), model.meshDeflection);
    });
  if (exact) {
    for (const Family f : {Family::U, Family::V}) {
      const SliceSet& set = a.slices(f);
      std::vector<int> needed;
      for (size_t i = 0; i < keys.size(); ++i)
        if (familyAt(keys[i].first) == f) needed.insert(needed.end(), chosen[i].begin(), chosen[i].end());
      std::sort(needed.begin(), needed.end());
      needed.erase(std::unique(needed.begin(), needed.end()), needed.end());
      std::vector<double> positions;
      for (int k : needed) positions.push_back(set.slices[k].position);
      // Where OCCT fails, the patches are emitted as the polygons the search checked (below:
      // a cylinder without its exact section, a patch whose slots cannot be cut).
      std::vector<ExactSlice> cut;
      if (deadline.passed()) continue;
      try {
        cut = sliceBrep(model.shape, set.frame, positions, exactDeflection(model.meshDeflection),
                        SliceDetail::FacesOnly);
      } catch (const Error&) {
        continue;
      }
      for (size_t i = 0; i < needed.size(); ++i) exactSlices[f][needed[i]] = cut[i];
    }
    // Not tried (the deadline passed: left unknown, for a later design to cut), or built,
    // or failed (a null shape: it would fail again).
    std::vector<std::optional<TopoDS_Shape>> built(keys.size());
    parallelFor(keys.size(), [&](size_t i) {
      const Family f = familyAt(keys[i].first);
      const Cylinder& c = a.cylinders(f)[keys[i].second];
      if (deadline.passed()) return;
      try {
        built[i] = occtGuard("building an exact patch", [&] {
          return exactSection(c, chosen[i], exactSlices[f], a.slices(f).frame, model.meshDeflection);
        });
      } catch (const Error&) {
        built[i] = TopoDS_Shape();  // a slice missing (its family's sections failed), or a fuse failed
      }
    });
    for (size_t i = 0; i < keys.size(); ++i)
      if (built[i]) sections[keys[i]] = *built[i];
  }

  const double crumb = std::max(0.5, r.params.width() * r.params.width());
  parallelFor(scaffold.patches.size(), [&](size_t k) {
    const ScaffoldPatch& p = scaffold.patches[k];
    const SliceFrame& frame = a.slices(p.family).frame;
    PatchFace& pf = out[k];
    if (!exact) {
      pf = polygonPatch(a, r, static_cast<int>(k));
      return;
    }
    const auto section0 = sections.find({familyIndex(p.family), p.cylinder});
    if (section0 == sections.end() || section0->second.IsNull() || deadline.passed()) {
      pf = polygonPatch(a, r, static_cast<int>(k), false);
      return;
    }
    pf.exact = true;
    try {
      occtGuard("cutting the slots of a patch", [&] {
        gp_Trsf onto;
        onto.SetTranslation(
            gp_Vec(frame.normal.x * p.position, frame.normal.y * p.position, frame.normal.z * p.position));
        const TopoDS_Shape section = section0->second.Moved(TopLoc_Location(onto));
        const std::vector<TopoDS_Shape> tools = slotFaces(slotShapes(r.cuts[k], r.params), frame, p.position);
        // Rebuilt from the section's and the slots' own edges, as the union is; the Boolean
        // cut where that is unsure (exact/rebuilt_faces.hpp).
        TopoDS_Shape slotted = section;
        if (!tools.empty())
          slotted = rebuiltFaces(
              {section, compound(tools)}, [](const std::vector<Region2d>& q) { return q[0].subtract(q[1]); },
              frame, p.position, exactDeflection(model.meshDeflection));
        if (slotted.IsNull()) slotted = boolean(faces(section), tools, true);
        std::vector<TopoDS_Shape> kept;
        std::vector<Region2d> polygons;  // of the kept faces: their union is the outline
        for (const TopoDS_Shape& f : faces(slotted)) {
          Region2d polygon = std::move(facePolygons(f, frame, kOutlineDeflection).front());
          if (!areaAtLeast(f, polygon, crumb)) continue;
          kept.push_back(f);
          polygons.push_back(std::move(polygon));
        }
        pf.pieces = static_cast<int>(kept.size());
        pf.shape = kept.size() == 1 ? kept.front() : compound(kept);
        pf.outline = Region2d::uniteAll(polygons);
        // Faces that overlap (a fuse that did not unify them) are one region to the checks
        // but a cut path each to the cutter: the patch is emitted as its polygon.
        if (pf.outline.components().size() < kept.size())
          throw Error(ErrorKind::Geometry, "the exact faces of a patch overlap");
      });
    } catch (const Error&) {
      pf = polygonPatch(a, r, static_cast<int>(k), false);
    }
  });
  return out;
}

bool areaAtLeast(const TopoDS_Shape& face, const Region2d& polygon, double least) {
  double perimeter = 0;
  for (const Region2d::Loop& loop : polygon.loops()) perimeter += Region2d::perimeter(loop);
  const double error = 2 * kOutlineDeflection * perimeter, approximate = polygon.area();
  if (approximate - error >= least) return true;
  if (approximate + error < least) return false;
  return area(face) >= least;
}

PatchFace polygonPatch(const Arrangement& a, const Realization& r, int k, bool simplify) {
  const ScaffoldPatch& p = a.scaffold.patches[k];
  PatchFace pf;
  // Simplified, the outline also loses its crumb holes: holes narrower than a quarter of
  // the tolerance it keeps (stanford-bunny.obj: a triangle 4 µm wide touching the outer
  // loop; the face failed BRepCheck and the sheet cut it).
  pf.outline = simplify ? withoutCrumbs(simplified(r.slotted[k], kOutlineDeflection), kOutlineDeflection / 4)
                        : r.slotted[k];
  pf.shape = facesFromRegion(pf.outline, a.slices(p.family).frame, p.position);
  pf.pieces = static_cast<int>(pf.outline.components().size());
  return pf;
}

TopoDS_Shape kerfCompensated(const TopoDS_Shape& shape, double kerf) {
  if (kerf <= 0) return shape;
  return occtGuard("compensating the kerf", [&] {
    std::vector<TopoDS_Shape> out;
    for (const TopoDS_Shape& f : faces(shape)) {
      BRepOffsetAPI_MakeOffset offset(TopoDS::Face(f), GeomAbs_Arc);
      offset.Perform(kerf / 2);
      if (!offset.IsDone()) throw Error(ErrorKind::Geometry, "cannot offset a patch outline by the kerf");
      out.push_back(offset.Shape());
    }
    return out.size() == 1 ? out.front() : compound(out);
  });
}

}  // namespace sliceform
