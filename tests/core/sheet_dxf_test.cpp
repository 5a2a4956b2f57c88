// SPDX-License-Identifier: LGPL-2.1-or-later
// The DXF sheet writer, read back with dxflib's own reader: layers and their colours, the
// header variables a laser cutter needs (units), every cut element as its own entity type
// with the geometry it was given (a clockwise arc as the counter-clockwise DXF arc over the
// same points), and labels kept off the cut layer.
#include <gtest/gtest.h>

#include <dl_creationadapter.h>
#include <dl_dxf.h>
#include <dl_writer_ascii.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "output/sheet_dxf.hpp"
#include "support/error.hpp"
#include "test_support.hpp"

namespace sliceform {
namespace {

constexpr double kTol = 1e-9;

// What the reader saw: every entity's type and layer, the geometry of each kind, the layer
// colours and the header variables.
class Capture : public DL_CreationAdapter {
 public:
  struct Entity {
    std::string type, layer;
    int colour;
  };
  std::vector<Entity> entities;
  std::vector<DL_LineData> lines;
  std::vector<DL_ArcData> arcs;
  std::vector<DL_CircleData> circles;
  std::vector<std::vector<Vec2>> polylines;
  std::map<std::string, int> layerColour;
  std::map<std::string, std::string> strings;
  std::map<std::string, int> ints;

  using DL_CreationAdapter::setVariableInt;
  using DL_CreationAdapter::setVariableString;

  void addLayer(const DL_LayerData& d) override { layerColour[d.name] = getAttributes().getColor(); }
  void addLine(const DL_LineData& d) override {
    note("LINE");
    lines.push_back(d);
  }
  void addArc(const DL_ArcData& d) override {
    note("ARC");
    arcs.push_back(d);
  }
  void addCircle(const DL_CircleData& d) override {
    note("CIRCLE");
    circles.push_back(d);
  }
  void addPolyline(const DL_PolylineData&) override {
    note("POLYLINE");
    polylines.emplace_back();
  }
  void addVertex(const DL_VertexData& v) override { polylines.back().push_back({v.x, v.y}); }
  void setVariableString(const std::string& key, const std::string& value, int) override {
    strings[key] = value;
  }
  void setVariableInt(const std::string& key, int value, int) override { ints[key] = value; }

  int count(const std::string& type, const std::string& layer) const {
    int n = 0;
    for (const Entity& e : entities) n += e.type == type && e.layer == layer;
    return n;
  }

 private:
  void note(const char* type) {
    entities.push_back({type, getAttributes().getLayer(), getAttributes().getColor()});
  }
};

CutElement line(Vec2 a, Vec2 b) {
  CutElement e;
  e.kind = CutElement::Kind::Line;
  e.a = a, e.b = b;
  return e;
}

CutElement arc(Vec2 centre, double radius, double start, double end, bool ccw) {
  CutElement e;
  e.kind = CutElement::Kind::Arc;
  e.centre = centre, e.radius = radius, e.start = start, e.end = end, e.ccw = ccw;
  e.a = {centre.x + radius * std::cos(start), centre.y + radius * std::sin(start)};
  e.b = {centre.x + radius * std::cos(end), centre.y + radius * std::sin(end)};
  return e;
}

CutElement circle(Vec2 centre, double radius) {
  CutElement e;
  e.kind = CutElement::Kind::Circle;
  e.centre = centre, e.radius = radius;
  return e;
}

// A square with a round hole, a "D" closed by a clockwise arc, a pie slice closed by a
// counter-clockwise arc, and one engraved stroke (an "L").
SheetDrawing drawing() {
  SheetDrawing d;
  d.cut.push_back({line({20, 20}, {60, 20}), line({60, 20}, {60, 60}), line({60, 60}, {20, 60}),
                   line({20, 60}, {20, 20})});
  d.cut.push_back({circle({40, 40}, 5)});
  d.cut.push_back({line({100, 20}, {100, 60}), arc({100, 40}, 20, M_PI / 2, -M_PI / 2, false)});
  d.cut.push_back(
      {arc({150, 40}, 10, 0, M_PI / 2, true), line({150, 50}, {150, 40}), line({150, 40}, {160, 40})});
  d.engrave.push_back({{30, 70}, {30, 80}, {35, 80}});
  return d;
}

Capture readBack(const std::string& path) {
  Capture capture;
  DL_Dxf dxf;
  EXPECT_TRUE(dxf.in(path, &capture)) << path;
  return capture;
}

Vec2 pointOn(const DL_ArcData& a, double degrees) {
  const double t = degrees * M_PI / 180;
  return {a.cx + a.radius * std::cos(t), a.cy + a.radius * std::sin(t)};
}

// The middle of a DXF arc, which runs counter-clockwise from angle1 to angle2.
Vec2 middle(const DL_ArcData& a) {
  const double sweep = std::fmod(a.angle2 - a.angle1 + 360, 360);
  return pointOn(a, a.angle1 + sweep / 2);
}

void expectNear(Vec2 p, Vec2 q) {
  EXPECT_NEAR(p.x, q.x, 1e-6);
  EXPECT_NEAR(p.y, q.y, 1e-6);
}

TEST(SheetDxf, LayersColoursAndUnits) {
  test::TempDir dir;
  const std::string path = dir.file("sheet.dxf");
  writeSheetDxf(drawing(), SheetSpec{}, path);
  const Capture c = readBack(path);
  EXPECT_EQ(c.layerColour.at("CUT"), 1);
  EXPECT_EQ(c.layerColour.at("ENGRAVE"), 5);
  EXPECT_EQ(c.strings.at("$ACADVER"), "AC1015");
  EXPECT_EQ(c.ints.at("$INSUNITS"), 4);
  EXPECT_EQ(c.ints.at("$MEASUREMENT"), 1);
  // Entities carry their layer's colour too, for laser software that ignores layers.
  for (const Capture::Entity& e : c.entities) EXPECT_EQ(e.colour, e.layer == "CUT" ? 1 : 5) << e.type;
}

TEST(SheetDxf, CutElementsKeepTheirKind) {
  test::TempDir dir;
  const std::string path = dir.file("sheet.dxf");
  writeSheetDxf(drawing(), SheetSpec{}, path);
  const Capture c = readBack(path);
  EXPECT_EQ(c.count("LINE", "CUT"), 7);
  EXPECT_EQ(c.count("ARC", "CUT"), 2);
  EXPECT_EQ(c.count("CIRCLE", "CUT"), 1);
  EXPECT_EQ(c.entities.size(), 11u);  // the ten cut elements and one stroke, no border
  ASSERT_EQ(c.lines.size(), 7u);
  EXPECT_NEAR(c.lines[0].x1, 20, kTol);
  EXPECT_NEAR(c.lines[0].y1, 20, kTol);
  EXPECT_NEAR(c.lines[0].x2, 60, kTol);
  EXPECT_NEAR(c.lines[0].y2, 20, kTol);
  ASSERT_EQ(c.circles.size(), 1u);
  EXPECT_NEAR(c.circles[0].cx, 40, kTol);
  EXPECT_NEAR(c.circles[0].cy, 40, kTol);
  EXPECT_NEAR(c.circles[0].radius, 5, kTol);
}

TEST(SheetDxf, ClockwiseArcBecomesTheCounterClockwiseArcOverTheSamePoints) {
  test::TempDir dir;
  const std::string path = dir.file("sheet.dxf");
  writeSheetDxf(drawing(), SheetSpec{}, path);
  const Capture c = readBack(path);
  ASSERT_EQ(c.arcs.size(), 2u);
  // Clockwise from 90° to -90° about (100, 40), through (120, 40): DXF 270° -> 90°.
  const DL_ArcData& cw = c.arcs[0];
  EXPECT_NEAR(cw.cx, 100, kTol);
  EXPECT_NEAR(cw.cy, 40, kTol);
  EXPECT_NEAR(cw.radius, 20, kTol);
  EXPECT_NEAR(cw.angle1, 270, 1e-9);
  EXPECT_NEAR(cw.angle2, 90, 1e-9);
  expectNear(pointOn(cw, cw.angle1), {100, 20});
  expectNear(pointOn(cw, cw.angle2), {100, 60});
  expectNear(middle(cw), {120, 40});
  // Counter-clockwise arcs keep their angles.
  const DL_ArcData& ccw = c.arcs[1];
  EXPECT_NEAR(ccw.angle1, 0, 1e-9);
  EXPECT_NEAR(ccw.angle2, 90, 1e-9);
  expectNear(middle(ccw), {150 + 10 * M_SQRT1_2, 40 + 10 * M_SQRT1_2});
}

TEST(SheetDxf, StrokesAreEngravedNotCut) {
  test::TempDir dir;
  const std::string path = dir.file("sheet.dxf");
  writeSheetDxf(drawing(), SheetSpec{}, path);
  const Capture c = readBack(path);
  EXPECT_EQ(c.count("POLYLINE", "ENGRAVE"), 1);
  EXPECT_EQ(c.count("POLYLINE", "CUT"), 0);
  for (const Capture::Entity& e : c.entities) {
    if (e.layer != "CUT") {
      EXPECT_EQ(e.type, "POLYLINE");
    }
  }
  ASSERT_EQ(c.polylines.size(), 1u);
  ASSERT_EQ(c.polylines[0].size(), 3u);
  expectNear(c.polylines[0][2], {35, 80});
}

// The largest handle (group code 5 or 105) after the header, which holds $HANDSEED itself.
long largestHandle(const std::string& path) {
  std::ifstream in(path);
  std::string code, value;
  bool pastHeader = false;
  long largest = 0;
  while (std::getline(in, code) && std::getline(in, value)) {
    const int c = std::stoi(code);
    if (c == 0 && value == "ENDSEC") pastHeader = true;
    if (pastHeader && (c == 5 || c == 105)) largest = std::max(largest, std::stol(value, nullptr, 16));
  }
  return largest;
}

// A mesh patch gives thousands of lines; $HANDSEED must stay above every handle dxflib gave.
TEST(SheetDxf, HandleSeedExceedsEveryHandle) {
  SheetDrawing d;
  CutLoop loop;
  for (int i = 0; i < 70000; ++i) loop.push_back(line({0.001 * i, 0}, {0.001 * (i + 1), 0}));
  d.cut.push_back(loop);
  test::TempDir dir;
  const std::string path = dir.file("many.dxf");
  writeSheetDxf(d, SheetSpec{}, path);
  const Capture c = readBack(path);
  EXPECT_EQ(c.count("LINE", "CUT"), 70000);
  EXPECT_GT(std::stol(c.strings.at("$HANDSEED"), nullptr, 16), largestHandle(path));
}

// What dxflib's own writer makes of a number: the oracle for ours, which formats them
// without sprintf (sheet_dxf.cpp's BufferedWriter).
std::string dxflibText(double value) {
  test::TempDir dir;
  const std::string path = dir.file("one.dxf");
  {
    DL_WriterA writer(path.c_str());
    writer.dxfReal(10, value);
    writer.close();
  }
  std::ifstream in(path);
  std::string code, text;
  std::getline(in, code);
  std::getline(in, text);
  return text;
}

TEST(SheetDxf, NumbersAreWrittenAsDxflibWritesThem) {
  const std::vector<double> values = {
      0.1,   1.0 / 3, -2.0 / 3, 123456.7890123,      1e-17, 2.5,  1e9 + 0.5,         0.1 + 0.2, -12.5,
      5e-17, -0.0,    7e-16,    199.999999999999999, 1e-5,  42.0, 3.0000000000000004};
  SheetDrawing d;
  CutLoop loop;
  for (size_t i = 0; i + 1 < values.size(); i += 2)
    loop.push_back(line({values[i], values[i + 1]}, {values[i + 1], values[i]}));
  d.cut.push_back(loop);
  test::TempDir dir;
  const std::string path = dir.file("numbers.dxf");
  writeSheetDxf(d, SheetSpec{}, path);
  // Each LINE's start and end points (group codes 10, 20, 11, 21), in the order written.
  std::ifstream in(path);
  std::string code, value;
  std::vector<std::string> written;
  bool line = false;
  while (std::getline(in, code) && std::getline(in, value)) {
    const int c = std::stoi(code);
    if (c == 0) line = value == "LINE";
    if (line && (c == 10 || c == 20 || c == 11 || c == 21)) written.push_back(value);
  }
  std::vector<std::string> expected;
  for (size_t i = 0; i + 1 < values.size(); i += 2)
    for (double v : {values[i], values[i + 1], values[i + 1], values[i]}) expected.push_back(dxflibText(v));
  EXPECT_EQ(written, expected);
}

TEST(SheetDxf, UnwritableFolderIsAnIoError) {
  test::TempDir dir;
  const std::string path = dir.file("missing/sheet.dxf");
  try {
    writeSheetDxf(drawing(), SheetSpec{}, path);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Io);
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace sliceform
