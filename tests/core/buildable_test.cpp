// SPDX-License-Identifier: LGPL-2.1-or-later
// The fabrication contract on solids that broke it: what is emitted is what was checked,
// and it can be built. Each design runs the whole pipeline and is checked again here on
// its emitted outlines (verify/emitted), as the independent checker would.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRep_Builder.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Quaternion.hxx>
#include <gp_Trsf.hxx>

#include <cmath>
#include <functional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "output/report_json.hpp"
#include "pipeline/design.hpp"
#include "pipeline/directions.hpp"
#include "support/error.hpp"
#include "test_support.hpp"

namespace sliceform {
namespace {

// Checks the emitted design as report.json carries it.
void expectBuildable(const Model& model, const Design& d, const DesignParams& params) {
  std::vector<Region2d> outlines;
  for (const PatchFace& f : d.patches) outlines.push_back(f.outline);
  const RealizationInput in = realizationInput(d.arrangement, model.meshDeflection);
  const Emitted e = checkEmitted(in, outlines, params.slots);
  // One outer loop per written outline, holes inside it, as the independent checker counts
  // them: a sliver the search would drop as a crumb is a second piece once written.
  for (size_t k = 0; k < outlines.size(); ++k)
    EXPECT_EQ(outlines[k].components().size(), 1u) << "patch " << k << (d.patches[k].exact ? " (exact)" : "");
  EXPECT_TRUE(e.collisions.empty()) << e.collisions.size() << " pairs, up to " << e.worstOverlap << " mm";
  EXPECT_EQ(e.splitPatches, 0);
  EXPECT_EQ(e.interlocks, 0);
  EXPECT_FALSE(tooClose(e, d.arrangement.minSpacing)) << e.minPatchSpacing << " mm";
  EXPECT_TRUE(d.certificate.stable) << d.certificate.reason;
  EXPECT_FALSE(d.realization.timedOut);
  // What is listed as a hinge is where both emitted patches meet.
  for (size_t h = 0; h < d.arrangement.scaffold.hinges.size(); ++h) EXPECT_EQ(e.meets[h], d.emitted.meets[h]);
  for (const std::string& p : designProblems(d)) ADD_FAILURE() << p;
}

// An assembly of touching solids, as CAD users model it: two plates joined by four rods
// standing on the lower plate and under the upper one, and a bar lying across the top.
// Each solid is its own shape in a compound. The rods' edges run along V-patches' lines:
// before grazes were moved off, two V-patches came out in pieces.
TopoDS_Shape rodsAndPlates() {
  BRep_Builder builder;
  TopoDS_Compound c;
  builder.MakeCompound(c);
  builder.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(120, 80, 6)).Shape());
  builder.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 60), gp_Pnt(120, 80, 66)).Shape());
  for (const double x : {20.0, 100.0})
    for (const double y : {20.0, 60.0})
      builder.Add(c, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, 6), gp_Dir(0, 0, 1)), 6, 54).Shape());
  builder.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(10, 34, 66), gp_Pnt(110, 46, 78)).Shape());
  return c;
}

TEST(Buildable, TouchingSolidsEmitWhatWasChecked) {
  DesignParams params;
  params.arrangement.slices = 64;
  const Model model = modelFromShape(rodsAndPlates(), "rods and plates");
  const Design d = runDesign(model, params);
  expectBuildable(model, d, params);
}

// The check after patches are replaced counts again only the replaced ones' pieces: what
// the design carries is what a whole check of its outlines finds, and pieces given as known
// are taken as given (a patch's pieces depend on its outline alone).
TEST(Buildable, ChecksAfterReplacingCountOnlyTheReplacedPieces) {
  DesignParams params;
  params.arrangement.slices = 64;
  const Model model = modelFromShape(rodsAndPlates(), "rods and plates");
  const Design d = runDesign(model, params);
  std::vector<Region2d> outlines;
  for (const PatchFace& f : d.patches) outlines.push_back(f.outline);
  const RealizationInput in = realizationInput(d.arrangement, model.meshDeflection);
  const Emitted whole = checkEmitted(in, outlines, params.slots);
  ASSERT_EQ(whole.pieces.size(), outlines.size());
  EXPECT_EQ(d.emitted.pieces, whole.pieces);
  EXPECT_EQ(d.emitted.split, whole.split);
  EXPECT_EQ(d.emitted.failing, whole.failing);
  std::vector<int> known = whole.pieces;
  known[1] = -1;
  EXPECT_EQ(checkEmitted(in, outlines, params.slots, &known).pieces, whole.pieces);
  known[0] = 2;  // not counted again: patch 0 reads as split
  const Emitted told = checkEmitted(in, outlines, params.slots, &known);
  EXPECT_EQ(told.split.front(), 0);
  EXPECT_EQ(told.splitPatches, whole.splitPatches + 1);
}

// A bone: a shaft with two round knobs at each end, lying aslant as a scanned bone lies.
// Where a knob's round meets the shaft, partner lines graze both patches at one height:
// before grazes were moved off, five patches came out in pieces at 64 slices, and exact
// faces cut there carried slivers that were written as second outer loops.
TopoDS_Shape bone(const gp_Vec& axis) {
  TopTools_ListOfShape shaft, knobs;
  shaft.Append(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 5, 120).Shape());
  for (const double z : {0.0, 120.0})
    for (const double x : {-5.0, 5.0}) knobs.Append(BRepPrimAPI_MakeSphere(gp_Pnt(x, 0, z), 9).Shape());
  BRepAlgoAPI_Fuse fuse;
  fuse.SetArguments(shaft);
  fuse.SetTools(knobs);
  fuse.Build();
  if (!fuse.IsDone()) throw std::runtime_error("the bone's Boolean failed");
  ShapeUpgrade_UnifySameDomain unify(fuse.Shape());
  unify.Build();
  gp_Trsf aslant;
  aslant.SetRotation(gp_Quaternion(gp_Vec(0, 0, 1), axis));
  return BRepBuilderAPI_Transform(unify.Shape(), aslant).Shape();
}

TEST(Buildable, BoneLyingAslantHasNoSplitPatch) {
  DesignParams params;
  params.arrangement.slices = 64;
  const Model model = scaledToSize(modelFromShape(bone({1, 0.2, 0.2}), "bone"), 150);  // as the CLI does
  const Design d = runDesign(model, params);
  EXPECT_GE(d.patches.size(), 6u);
  expectBuildable(model, d, params);
}

// The bone at 45 degrees, at the default slices: 26 of its 49 exact faces came out of the
// slot Booleans with a sliver loop, written to report.json as a second outer loop while
// the run's own check (crumbs dropped) passed it.
TEST(Buildable, BoneAt45DegreesWritesOneLoopPerPatch) {
  DesignParams params;
  const Model model = scaledToSize(modelFromShape(bone({1, 0, 1}), "bone"), 150);
  const Design d = runDesign(model, params);
  EXPECT_GE(d.patches.size(), 20u);
  expectBuildable(model, d, params);
}

// A level-2 Menger sponge (a cube less, along each axis, the square tunnels of a level-2
// Sierpinski carpet), stood on a corner: every slice is lace. The slot search ran for
// more than 600 s on it; the neck test grew whole patches back at every move.
TopoDS_Shape mengerSponge(double side) {
  TopTools_ListOfShape tools;
  const auto tunnel = [&](int axis, double a, double b, double s) {
    const double lo[3] = {axis == 0 ? -1 : a, axis == 1 ? -1 : (axis == 0 ? a : b), axis == 2 ? -1 : b};
    const double size[3] = {axis == 0 ? side + 2 : s, axis == 1 ? side + 2 : s, axis == 2 ? side + 2 : s};
    tools.Append(BRepPrimAPI_MakeBox(gp_Pnt(lo[0], lo[1], lo[2]), size[0], size[1], size[2]).Shape());
  };
  for (int axis = 0; axis < 3; ++axis) {
    tunnel(axis, side / 3, side / 3, side / 3);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (i != 1 || j != 1) tunnel(axis, i * side / 3 + side / 9, j * side / 3 + side / 9, side / 9);
  }
  TopTools_ListOfShape cube;
  cube.Append(BRepPrimAPI_MakeBox(side, side, side).Shape());
  BRepAlgoAPI_Cut cut;
  cut.SetArguments(cube);
  cut.SetTools(tools);
  cut.Build();
  if (!cut.IsDone()) throw std::runtime_error("the sponge's Boolean failed");
  gp_Trsf onCorner;
  onCorner.SetRotation(gp_Quaternion(gp_Vec(1, 1, 1), gp_Vec(0, 0, 1)));
  return BRepBuilderAPI_Transform(cut.Shape(), onCorner).Shape();
}

TEST(Buildable, MengerSpongeOnItsCornerEndsAndBuilds) {
  DesignParams params;
  // 32 slices a direction: 112 patches, 1226 hinges. (At the default 128 the design ends
  // within its time limit, with one interlock left: docs/decisions.md.)
  params.arrangement.slices = 32;
  const Model model = modelFromShape(mengerSponge(81), "Menger sponge");
  const Design d = runDesign(model, params);
  EXPECT_GT(d.patches.size(), 50u);
  expectBuildable(model, d, params);
}

// A FreeCAD edit designs the same model again with the design before it (runDesign's
// `earlier`): the stages whose inputs are the same are taken from it, and the design is the
// one made from nothing, byte for byte in report.json, whatever was edited.
TEST(Buildable, DesigningAgainTakesOnlyStagesWhoseInputsAreTheSame) {
  const Model model = modelFromMesh(modelFromShape(test::makeTorus(60, 20), "torus").mesh, "torus mesh");
  DesignParams first;
  first.arrangement.slices = 32;
  const Design before = runDesign(model, first);
  struct Edit {
    const char* what;
    std::function<void(DesignParams&)> apply;
    int taken;  // slice, reeb, gca
  };
  const std::vector<Edit> edits = {
      {"thickness", [](DesignParams& p) { p.slots.thickness = 0.5; }, 3},
      {"clearance", [](DesignParams& p) { p.slots.clearance = 0.2; }, 3},
      {"spacing the cylinders must keep", [](DesignParams& p) { p.arrangement.stabilize.minSpacing = 14; },
       2},
      {"tauA", [](DesignParams& p) { p.arrangement.tauA = 0.2; }, 2},
      {"tauM", [](DesignParams& p) { p.arrangement.tauM = 0.1; }, 1},
      {"slices", [](DesignParams& p) { p.arrangement.slices = 36; }, 0},
      {"directions",
       [](DesignParams& p) {
         p.arrangement.u = {0, 1, 0}, p.arrangement.v = {-1, 0, 0};
       },
       0},
  };
  for (const Edit& e : edits) {
    DesignParams params = first;
    e.apply(params);
    const Design again = runDesign(model, params, {}, {}, nullptr, &before);
    const Design fresh = runDesign(model, params);
    EXPECT_EQ(again.arrangement.stagesTaken, e.taken) << e.what;
    EXPECT_EQ(fresh.arrangement.stagesTaken, 0) << e.what;
    // The quality's measures of the slices and cylinders are taken with the cylinders.
    EXPECT_EQ(again.arrangement.qualityBase == before.arrangement.qualityBase, e.taken == 3) << e.what;
    EXPECT_EQ(reportJson(model, params, again).dump(), reportJson(model, params, fresh).dump()) << e.what;
  }
  // With the directions chosen for the model: the full design in the frame chosen before
  // takes its stages, and the design is the one made from nothing.
  DesignParams thick = first;
  thick.slots.thickness = 0.5;
  DirectionChoice c0, c1, c2;
  const Design autoBefore = designInBestFrame(model, first, c0);
  const Design autoAgain = designInBestFrame(model, thick, c1, {}, {}, nullptr, &autoBefore);
  const Design autoFresh = designInBestFrame(model, thick, c2);
  ASSERT_EQ(c1.chosen, c0.chosen);  // the torus: the same frame at either thickness
  EXPECT_EQ(autoAgain.arrangement.stagesTaken, 3);
  thick.arrangement.u = c1.trials[c1.chosen].u, thick.arrangement.v = c1.trials[c1.chosen].v;
  EXPECT_EQ(reportJson(model, thick, autoAgain).dump(), reportJson(model, thick, autoFresh).dump());
  // The edits changed the design (else the comparison above says nothing).
  DesignParams thicker = first;
  thicker.slots.thickness = 0.5;
  EXPECT_NE(reportJson(model, first, before).dump(),
            reportJson(model, thicker, runDesign(model, thicker)).dump());
}

// A frame that other frames follow when it cannot be built (the CLI's file axes) is not
// repaired where more patches are in pieces than the repair mends: occ/Top.brep at its file
// axes and 48 slices leaves 4. The repair, asked for later (the file's axes kept after
// all), takes the design's first stages and makes the design an Always repair makes.
TEST(Buildable, ManyPatchesInPiecesAreLeftToOtherFrames) {
  const Model model = scaledToSize(readModel(SLICEFORM_OCCT_DATA_DIR "/occ/Top.brep"), 150);
  DesignParams params;
  params.arrangement.slices = 48;
  const Design left = designPatches(model, params, {}, nullptr, nullptr, SplitRepair::WhenFew);
  EXPECT_TRUE(left.grazes.splitLeft);
  EXPECT_GT(left.realization.splitPatches + left.realization.lostPins, 2);
  EXPECT_EQ(left.grazes.splitMoved + left.grazes.splitDropped, 0);
  EXPECT_FALSE(designProblems(left).empty());
  EXPECT_THROW(reportJson(model, params, left), std::invalid_argument);  // not laid out
  Design repaired = designPatches(model, params, {}, nullptr, &left);
  Design always = designPatches(model, params);
  layOutDesign(repaired, params.sheet);
  layOutDesign(always, params.sheet);
  EXPECT_EQ(repaired.arrangement.stagesTaken, 3);
  EXPECT_FALSE(repaired.grazes.splitLeft);
  EXPECT_FALSE(always.grazes.splitLeft);
  EXPECT_GT(always.grazes.splitMoved + always.grazes.splitDropped, 0);  // the repair tried, and kept a change
  EXPECT_EQ(reportJson(model, params, repaired).dump(), reportJson(model, params, always).dump());
}

// A BRep solid edited the way the FreeCAD feature redesigns: the exact sections of the
// cylinders the edit keeps are taken from the design before, not cut from the solid again,
// and the design is the one made from nothing.
TEST(Buildable, DesigningAgainTakesTheExactSectionsOfTheCylindersItKeeps) {
  const Model model =
      modelFromShape(test::makeBoxWithHoles(80, 60, 60, {{40, 30, 15}}), "box minus a cylinder");
  DesignParams first;
  first.arrangement.slices = 30;  // 2.67 and 2 mm apart: either slot keeps patches a slice and two apart
  const Design before = runDesign(model, first);
  ASSERT_GT(before.exactSections.byCylinder.size(), 0u);
  EXPECT_EQ(before.exactSections.taken, 0);
  for (const auto& [key, shape] : before.exactSections.byCylinder) EXPECT_FALSE(shape.IsNull());
  // A wider slot (the spacing the cylinders keep is the same, unlike at a thickness of 0.5).
  DesignParams wider = first;
  wider.slots.clearance = 0.3;
  const Design again = runDesign(model, wider, {}, {}, nullptr, &before);
  const Design fresh = runDesign(model, wider);
  ASSERT_EQ(again.arrangement.stagesTaken, 3);
  // Every cylinder with a patch found its section: none was cut again.
  std::set<std::pair<int, int>> used;
  for (const ScaffoldPatch& p : again.arrangement.scaffold.patches)
    used.insert({p.family == Family::U ? 0 : 1, p.cylinder});
  EXPECT_EQ(again.exactSections.taken, static_cast<int>(used.size()));
  EXPECT_EQ(fresh.exactSections.taken, 0);
  EXPECT_EQ(reportJson(model, wider, again).dump(), reportJson(model, wider, fresh).dump());
  EXPECT_NE(reportJson(model, first, before).dump(), reportJson(model, wider, fresh).dump());
  ASSERT_EQ(again.patches.size(), fresh.patches.size());
  for (size_t k = 0; k < again.patches.size(); ++k) {
    EXPECT_TRUE(again.patches[k].exact) << k;
    EXPECT_EQ(again.patches[k].exact, fresh.patches[k].exact) << k;
    EXPECT_EQ(again.patches[k].outline.area(), fresh.patches[k].outline.area()) << k;
  }
  // Other slices are other cylinders: nothing is taken.
  DesignParams more = first;
  more.arrangement.slices = 32;
  const Design other = runDesign(model, more, {}, {}, nullptr, &before);
  EXPECT_EQ(other.arrangement.stagesTaken, 0);
  EXPECT_EQ(other.exactSections.taken, 0);
}

// Every face a CAD program reads from the assembly passes BRepCheck: on the occt-misc parts
// whose faces did not (a 5° crossing of a circle and a slot's wall on Ball.brep trimmed
// where the polygons cross; a crumb hole and a crossing Newton slid along on Bottom.brep; a
// 0.16 µm spike back along a slot's wall on MODERN_Exhaust_1.brep, whose file axes give no
// buildable design).
TEST(Buildable, ExactFacesPassBRepCheck) {
  for (const char* name : {"Ball", "Bottom", "MODERN_Exhaust_1"}) {
    const Model model =
        scaledToSize(readModel(std::string(SLICEFORM_OCCT_DATA_DIR "/occ/") + name + ".brep"), 150);
    DesignParams params;
    // As the CLI does: the file's axes, other frames where they give no buildable design.
    Design d;
    try {
      d = designPatches(model, params);
    } catch (const Error&) {
    }
    if (d.patches.empty() || !designProblems(d).empty()) {
      DirectionChoice choice;
      d = designInBestFrame(model, params, choice);
    }
    ASSERT_TRUE(designProblems(d).empty()) << name;
    int faces = 0, exact = 0;
    for (const PatchFace& p : d.patches) {
      exact += p.exact;
      for (TopExp_Explorer f(p.shape, TopAbs_FACE); f.More(); f.Next(), ++faces)
        EXPECT_TRUE(BRepCheck_Analyzer(f.Current()).IsValid()) << name << ", face " << faces;
    }
    // Mostly exact faces, which are the ones at stake (OCCT 7.6.3: 54 of 56, 84 of 85, 5 of
    // 5; OCCT 7.8.1: MODERN_Exhaust_1 5 of 6).
    EXPECT_GE(5 * exact, 4 * static_cast<int>(d.patches.size())) << name;
  }
}

}  // namespace
}  // namespace sliceform
