// SPDX-License-Identifier: LGPL-2.1-or-later
// Exact patch geometry: the faces that get cut. The search stages work on polygons; here
// every patch is rebuilt for output, on its plane in 3D at the popped-up pose:
//  - BRep sources: the exact sections of the solid at each slice of the patch's cylinder
//    (only the faces of the cylinder's part), moved onto the patch plane and combined:
//    rebuilt from their exact edges along the union of their polygons (exact/rebuilt_faces.hpp),
//    or where that is unsure fused and cleaned with ShapeUpgrade_UnifySameDomain, so circles
//    stay circles. Pieces the polygon section
//    has and the slices do not (small branches the Reeb simplification merged in from other
//    slices) are added as polygons;
//  - mesh sources: the polygon section itself, simplified within kOutlineDeflection;
// then the slots are cut (rectangles, and circles for round ends).
#pragma once

#include <TopoDS_Shape.hxx>

#include <map>
#include <utility>
#include <vector>

#include "arrangement/arrange.hpp"
#include "model/model.hpp"
#include "realization/realize.hpp"
#include "support/deadline.hpp"

namespace sliceform {

struct PatchFace {
  TopoDS_Shape shape;  // planar face(s) in 3D; one face unless the patch fell apart
  Region2d outline;    // the same, polygonised finely, in the family frame's 2D coordinates
  int pieces = 0;      // faces after slotting (crumbs dropped): must be 1
  bool exact = false;  // built from exact sections (BRep source)
};

// Each cylinder's exact cross-section at position 0 of its frame, by (family: 0 U, 1 V;
// cylinder), as exactPatches cuts it from the solid before any slot: a null shape where
// OCCT failed (that cylinder's patches are the search's polygons). A section depends on the
// model and its cylinder alone, so a design made again with the cylinders of an earlier one
// (Arrangement::stagesTaken == 3: most Thickness, Clearance or Kerf edits) starts from the
// earlier design's sections and cuts only those of cylinders new to it: on occt-misc
// Bottom.brep a Clearance edit then spends 3.5 s in this stage (the slots) instead of 15.7.
struct ExactSections {
  std::map<std::pair<int, int>, TopoDS_Shape> byCylinder;
  int taken = 0;  // how many of those the last exactPatches used were there before it
};

// Once `deadline` has passed, the patches not yet cut are the search's polygons.
// `sections`: the sections known so far, taken where there and added to (see above); none
// when null.
std::vector<PatchFace> exactPatches(const Model& model, const Arrangement& arrangement,
                                    const Realization& realization, const Deadline& deadline = {},
                                    ExactSections* sections = nullptr);

// Patch k as the slotted polygon the search made, simplified within kOutlineDeflection or
// not at all: what a mesh source emits, and (unsimplified) what replaces an exact face or a
// simplified polygon that breaks a rule the search's own polygon keeps.
PatchFace polygonPatch(const Arrangement& arrangement, const Realization& realization, int k,
                       bool simplify = true);

// Planar faces of a region on the plane at `position` of `frame`, one per component.
TopoDS_Shape facesFromRegion(const Region2d& region, const SliceFrame& frame, double position);

// The kerf-compensated cut path of a patch: its boundary wires moved away from the paper
// by half the kerf (outer loops grow, holes and slots shrink), arcs kept as arcs. The
// result is wires: what the cutter follows, not paper.
TopoDS_Shape kerfCompensated(const TopoDS_Shape& faces, double kerf);

// Whether the planar face is at least `least` mm², read from `polygon` (its loops within
// kOutlineDeflection) where the polygon's error cannot decide it: less than the deflection
// times its perimeter, twice over. OCCT's surface integration only near the bound: it was
// 2 ms a face on the curved sections of occ/Bottom.brep, 9 % of its exact patches' CPU.
bool areaAtLeast(const TopoDS_Shape& face, const Region2d& polygon, double least);

// How far the output polygons may stray from the exact edges, mm. A mesh patch's outline
// is simplified within it (geometry/simplify.hpp): at 0.01 mm, far below any cutter's kerf,
// a third of rocker-arm's 26,000 points go, so every file and the layout handle fewer edges
// (OCCT's STEP writer is quadratic in the edges of a face). Slot corners turn by 90° and stay.
constexpr double kOutlineDeflection = 0.01;

// Which of a cylinder's sections (their polygons) add to their union, largest first: a
// section within `tolerance` (mm) of those already taken is left out. Only these are fused
// into the exact patch, as each Boolean fuse costs milliseconds, and along a prismatic
// stretch or under a bulge most sections lie inside another. Called with twice the polygon
// deflection: what is left out then lies within that distance of the patch, which nothing
// downstream sees (the polygon check that follows drops slivers up to 4 mesh deflections
// wide).
std::vector<size_t> sectionsAddingToUnion(const std::vector<Region2d>& sections, double tolerance);

}  // namespace sliceform
