// SPDX-License-Identifier: LGPL-2.1-or-later
// Slicing directions chosen for the model: the frame follows the model when it is turned,
// a model lying on its side is stood up, and every frame tried is reported.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <STEPControl_Reader.hxx>
#include <TopTools_ListOfShape.hxx>
#include <gp_Trsf.hxx>

#include <cmath>

#include "assembly/fold.hpp"
#include "output/design_files.hpp"
#include "output/report_json.hpp"
#include "pipeline/directions.hpp"
#include "test_support.hpp"

namespace sliceform {
namespace {

// A table: a top on four legs of different lengths' spans, so its principal axes are
// distinct and it stands on its legs only.
TopoDS_Shape table() {
  TopTools_ListOfShape top, legs;
  top.Append(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 50), gp_Pnt(120, 60, 60)).Shape());
  for (const double x : {5.0, 105.0})
    for (const double y : {5.0, 45.0})
      legs.Append(BRepPrimAPI_MakeBox(gp_Pnt(x, y, 0), gp_Pnt(x + 10, y + 10, 50)).Shape());
  BRepAlgoAPI_Fuse fuse;
  fuse.SetArguments(top);
  fuse.SetTools(legs);
  fuse.Build();
  if (!fuse.IsDone()) throw std::runtime_error("the table's Boolean failed");
  return fuse.Shape();
}

gp_Trsf turn(const gp_Ax1& axis, double degrees) {
  gp_Trsf t;
  t.SetRotation(axis, degrees * M_PI / 180);
  return t;
}

Vec3 apply(const gp_Trsf& t, const Vec3& v) {
  gp_Vec g(v.x, v.y, v.z);
  g.Transform(t);
  return {g.X(), g.Y(), g.Z()};
}

DesignParams coarse() {
  DesignParams p;
  p.arrangement.slices = 48;
  return p;
}

TEST(Directions, TurnedModelGetsTheSameDesignTurned) {
  const gp_Trsf r = turn(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 2, 3)), 40);
  DirectionChoice plain, turned;
  const Design a = designInBestFrame(modelFromShape(table(), "table"), coarse(), plain);
  const Design b = designInBestFrame(
      modelFromShape(BRepBuilderAPI_Transform(table(), r).Shape(), "turned table"), coarse(), turned);
  ASSERT_GE(plain.chosen, 0);
  ASSERT_GE(turned.chosen, 0);
  const FrameTrial &pa = plain.trials[plain.chosen], &pb = turned.trials[turned.chosen];
  // The same frame, turned: each family's normal, up to its sign.
  EXPECT_GT(std::abs(dot(apply(r, pa.u), pb.u)), 0.999) << pa.name << " / " << pb.name;
  EXPECT_GT(std::abs(dot(apply(r, pa.v), pb.v)), 0.999) << pa.name << " / " << pb.name;
  // And the same design.
  EXPECT_EQ(a.patches.size(), b.patches.size());
  EXPECT_NEAR(a.arrangement.quality.volumeIou, b.arrangement.quality.volumeIou, 0.02);
  EXPECT_TRUE(designProblems(a).empty());
  EXPECT_TRUE(designProblems(b).empty());
}

// A lamp: a round foot, a stem and a ball on top. It stands on its foot only: on its side
// or on the ball it would roll.
TopoDS_Shape lamp() {
  TopTools_ListOfShape foot, rest;
  foot.Append(BRepPrimAPI_MakeCylinder(40, 6).Shape());
  rest.Append(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, 6), gp_Dir(0, 0, 1)), 8, 60).Shape());
  rest.Append(BRepPrimAPI_MakeSphere(gp_Pnt(0, 0, 90), 30).Shape());
  BRepAlgoAPI_Fuse fuse;
  fuse.SetArguments(foot);
  fuse.SetTools(rest);
  fuse.Build();
  if (!fuse.IsDone()) throw std::runtime_error("the lamp's Boolean failed");
  return fuse.Shape();
}

TEST(Directions, ModelOnItsSideIsStoodUp) {
  // The lamp lying on its side, as a Y-up file puts it for a Z-up reader.
  const gp_Trsf side = turn(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)), -90);
  const Model model = modelFromShape(BRepBuilderAPI_Transform(lamp(), side).Shape(), "lamp on its side");
  const Vec3 footDown = apply(side, {0, 0, 1});
  EXPECT_TRUE(standsUp(model.mesh, footDown));
  EXPECT_FALSE(standsUp(model.mesh, footDown * -1.0));  // on the ball
  EXPECT_FALSE(standsUp(model.mesh, {0, 0, 1}));        // on its side, as the file has it
  DirectionChoice choice;
  const Design d = designInBestFrame(model, coarse(), choice);
  const FrameTrial& c = choice.trials[choice.chosen];
  EXPECT_TRUE(c.stands);
  EXPECT_GT(dot(cross(c.u, c.v), footDown), 0.999) << c.name;
  // Every frame tried is there, each scored, the chosen one designed and buildable.
  EXPECT_GE(choice.trials.size(), 8u);
  for (const FrameTrial& t : choice.trials) EXPECT_TRUE(t.score > 0 || !t.failure.empty()) << t.name;
  EXPECT_TRUE(c.designed);
  EXPECT_TRUE(c.buildable);
  EXPECT_TRUE(c.laidOut);
  EXPECT_EQ(c.sheets, d.layout.packing.sheets);
  for (const FrameTrial& t : choice.trials)  // not laid out: lost on buildability
    if (t.designed && !t.laidOut) EXPECT_FALSE(t.buildable) << t.name;
  EXPECT_FALSE(choice.why.empty());
  EXPECT_TRUE(d.directions.automatic);
}

// A FreeCAD edit of the slots (Thickness, Clearance) leaves the frames' estimates as they
// were: the design made from an earlier one takes them, designs only the best frame again,
// and is the design made afresh. So does a Slices edit above the estimates' slices; one
// below them estimates again.
TEST(Directions, AnEditTheEstimatesDoNotReadTakesThemAndGivesTheFreshDesign) {
  const Model model = modelFromShape(table(), "table");
  DirectionChoice first, edited, fresh, resliced;
  const Design a = designInBestFrame(model, coarse(), first);
  EXPECT_FALSE(first.estimatesTaken);
  DesignParams p = coarse();
  p.slots.clearance += 0.1;
  p.slots.thickness += 0.05;
  const Design b = designInBestFrame(model, p, edited, {}, {}, nullptr, &a);
  const Design c = designInBestFrame(model, p, fresh);
  EXPECT_TRUE(edited.estimatesTaken);
  EXPECT_FALSE(fresh.estimatesTaken);
  ASSERT_EQ(edited.chosen, fresh.chosen);
  DesignParams chosen = p;
  chosen.arrangement.u = fresh.trials[fresh.chosen].u, chosen.arrangement.v = fresh.trials[fresh.chosen].v;
  EXPECT_EQ(reportJson(model, chosen, b).dump(), reportJson(model, chosen, c).dump());
  // The edit did change the design: the slots are wider.
  EXPECT_NE(reportJson(model, chosen, b).dump(), reportJson(model, chosen, a).dump());
  DesignParams more = coarse();
  more.arrangement.slices = kEstimateSlices + 4;  // coarse() has 48: both above
  DirectionChoice again, afresh;
  const Design d = designInBestFrame(model, more, again, {}, {}, nullptr, &a);
  const Design e = designInBestFrame(model, more, afresh);
  EXPECT_TRUE(again.estimatesTaken);
  ASSERT_EQ(again.chosen, afresh.chosen);
  more.arrangement.u = afresh.trials[afresh.chosen].u, more.arrangement.v = afresh.trials[afresh.chosen].v;
  EXPECT_EQ(reportJson(model, more, d).dump(), reportJson(model, more, e).dump());
  DesignParams fewer = coarse();
  fewer.arrangement.slices = kEstimateSlices - 10;
  designInBestFrame(model, fewer, resliced, {}, {}, nullptr, &a);
  EXPECT_FALSE(resliced.estimatesTaken);
}

// A frame designed already (the file's axes, which the CLI designs first and which may
// rank first among the frames: Motor-c.brep) is not designed again: its trial takes the
// design given, and the result is the one designing it gives.
TEST(Directions, AFrameDesignedAlreadyIsNotDesignedAgain) {
  const Model model = modelFromShape(table(), "table");
  DirectionChoice plain;
  const Design a = designInBestFrame(model, coarse(), plain);
  DesignParams p = coarse();
  p.arrangement.u = plain.trials[plain.chosen].u, p.arrangement.v = plain.trials[plain.chosen].v;
  const Design made = designPatches(model, p);
  DirectionChoice reused;
  const Design b = designInBestFrame(model, coarse(), reused, {}, {}, nullptr, nullptr, &made);
  ASSERT_EQ(reused.chosen, plain.chosen);
  EXPECT_EQ(reportJson(model, p, b).dump(), reportJson(model, p, a).dump());
  // What the trial reads is the design given: marked as out of time, it cannot be built.
  Design marked = made;
  marked.grazes.timedOut = true;
  DirectionChoice taken;
  designInBestFrame(model, coarse(), taken, {}, {}, nullptr, nullptr, &marked);
  EXPECT_TRUE(taken.trials[plain.chosen].designed);
  EXPECT_FALSE(taken.trials[plain.chosen].buildable);
  EXPECT_NE(taken.chosen, plain.chosen);
}

// A buildable design is heard of before its layout (its 3D files begin beside the layout,
// as the file's axes' do), and the last design heard of is the one returned.
TEST(Directions, ABuildableDesignIsHeardOfBeforeItsLayout) {
  const Model model = modelFromShape(table(), "table");
  std::vector<std::pair<Vec3, bool>> heard;  // the frame's U, and whether it was laid out
  DirectionChoice choice;
  const Design d = designInBestFrame(model, coarse(), choice, {}, [&](const Design& ready) {
    heard.emplace_back(ready.arrangement.params.u, ready.layout.packing.sheets > 0);
  });
  ASSERT_TRUE(choice.trials[choice.chosen].buildable);
  ASSERT_FALSE(heard.empty());
  EXPECT_FALSE(heard.front().second);
  for (const auto& [u, laidOut] : heard) EXPECT_EQ(u, d.arrangement.params.u);
  EXPECT_GT(d.layout.packing.sheets, 0);
}

double boxDiagonal(const TopoDS_Shape& s) {
  Bnd_Box box;
  BRepBndLib::Add(s, box);
  return box.CornerMin().Distance(box.CornerMax());
}

// Files begun for a design in one frame give way to a design in another (its layout failed,
// and the directions went on): assembly.step is the later design's. The same frame again
// changes nothing.
TEST(Directions, FilesBegunForOneFrameGiveWayToAnother) {
  const Model model = modelFromShape(table(), "table");
  const Design first = runDesign(model, coarse());
  DesignParams turned = coarse();
  turned.arrangement.u = {0, 1, 0}, turned.arrangement.v = {0, 0, 1};
  const Design second = runDesign(model, turned);
  const double wanted = boxDiagonal(assemble(second.arrangement, second.patches, 60));
  ASSERT_GT(std::abs(boxDiagonal(assemble(first.arrangement, first.patches, 60)) - wanted), 1.0);
  test::TempDir dir;
  {
    DesignFilesWriter writer(dir.file("out"), 60);
    writer.start(first);
    writer.start(second);
    writer.start(second);
    writer.finish(model, turned, second);
  }
  STEPControl_Reader reader;
  ASSERT_EQ(reader.ReadFile(dir.file("out/assembly.step").c_str()), IFSelect_RetDone);
  reader.TransferRoots();
  EXPECT_NEAR(boxDiagonal(reader.OneShape()), wanted, 0.1);
  for (const auto& entry : std::filesystem::directory_iterator(dir.file("out")))
    EXPECT_NE(entry.path().filename().string().rfind(".assembly-", 0), 0u) << entry.path();
}

}  // namespace
}  // namespace sliceform
