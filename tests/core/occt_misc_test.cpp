// SPDX-License-Identifier: LGPL-2.1-or-later
// Every OCCT sample model (occt-misc): read, refuse cleanly or slice with both slicers.
#include <gtest/gtest.h>

#include <map>

#include <BRepAdaptor_Curve.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "model/model.hpp"
#include "slicing/brep_slicer.hpp"
#include "slicing/edge_samples.hpp"
#include "slicing/mesh_slicer.hpp"
#include "support/error.hpp"

namespace sliceform {
namespace {

namespace fs = std::filesystem;
const std::string kData = SLICEFORM_OCCT_DATA_DIR;

// The sample files, sorted; a single empty name (the test skips) if OCCT's data is missing.
std::vector<std::string> sampleFiles() {
  const std::pair<const char*, const char*> kinds[] = {
      {"occ", ".brep"}, {"step", ".step"}, {"iges", ".iges"}, {"stl", ".stl"}};
  std::vector<std::string> files;
  for (const auto& [folder, ext] : kinds) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(fs::path(kData) / folder, ec))
      if (entry.is_regular_file() && entry.path().extension() == ext) files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) files.push_back("");
  return files;
}

std::string testName(const testing::TestParamInfo<std::string>& info) {
  if (info.param.empty()) return "no_data";
  const fs::path p(info.param);
  std::string name = p.parent_path().filename().string() + "_" + p.filename().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

// Total length of the edges of `faces`.
double perimeter(const TopoDS_Shape& faces) {
  GProp_GProps props;
  BRepGProp::LinearProperties(faces, props);
  return props.Mass();
}

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The mesh and exact areas of a plane agree within `tolerance`. Where the section jumps
// within the mesh deflection d of the plane (a face parallel to the plane, or tangent to
// it), the two slicers may land on different sides of the jump: there both areas must lie
// within the jump, as measured by both slicers at position -/+ d.
void expectAgreement(const Model& model, const SliceFrame& frame, double position, double meshArea,
                     double exactArea, double tolerance, double deflection) {
  if (std::fabs(meshArea - exactArea) <= tolerance) return;
  const double d = model.meshDeflection;
  const SliceSet around = sliceMesh(model.mesh, frame, {position - d, position + d});
  const double below = around.slices[0].region.area(), above = around.slices[1].region.area();
  if (std::fabs(below - above) <= tolerance) {
    ADD_FAILURE() << "mesh area " << meshArea << " and exact area " << exactArea << " differ by more than "
                  << tolerance << " at " << position << ", where the section does not jump";
    return;
  }
  const std::vector<ExactSlice> exact =
      sliceBrep(model.shape, frame, {position - d, position + d}, deflection);
  // Region areas: they unite overlapping solids, as the mesh slicer does.
  const double exactBelow = exact[0].region.area(), exactAbove = exact[1].region.area();
  const double lo = std::min({below, above, exactBelow, exactAbove});
  const double hi = std::max({below, above, exactBelow, exactAbove});
  std::cout << "[occt-misc] the section jumps from " << below << " to " << above << " mm2 (mesh; exact "
            << exactBelow << " to " << exactAbove << ") within " << d << " mm of " << position << ": mesh "
            << meshArea << ", exact " << exactArea << "\n";
  EXPECT_GE(std::min(meshArea, exactArea), lo - tolerance) << "at " << position;
  EXPECT_LE(std::max(meshArea, exactArea), hi + tolerance) << "at " << position;
}

// The samples that are not closed solids, and why: everything else must be accepted, so a
// change that starts refusing valid solids fails here.
const std::map<std::string, const char*> kRefused = {
    {"bearing.iges", "no closed solid"},
    {"hammer.iges", "no closed solid"},
    {"MAT.brep", "no closed solid"},
    {"Room.brep", "no closed solid"},
    {"asahi.brep", "no closed solid"},
    {"edge.brep", "no closed solid"},
    {"face.brep", "no closed solid"},
    {"face1.brep", "no closed solid"},
    {"face2.brep", "no closed solid"},
    {"hammer.brep", "no closed solid"},
    {"shell1.brep", "no closed solid"},
    {"terrain.brep", "no closed solid"},
    // TR12J_OCC64K.stl's two small holes (6 edges) are filled on reading: it is accepted.
    {"wing.brep", "no closed solid"},
    {"bearing.stl", "not closed"},
    {"head.stl", "not closed"},
    {"motor.stl", "not closed"},
    {"video_part.stl", "not closed"},
};

class OcctSample : public testing::TestWithParam<std::string> {};

TEST_P(OcctSample, ReadsAndSlicesOrRefusesCleanly) {
  const std::string path = GetParam();
  if (path.empty()) GTEST_SKIP() << kData << " holds no sample models";
  const std::string name = fs::path(path).filename().string();

  auto start = std::chrono::steady_clock::now();
  Model model;
  try {
    model = readModel(path);
    requireClosed(model);
  } catch (const Error& e) {
    // Not a solid, or an open mesh: refused with a message for the user.
    EXPECT_EQ(e.kind(), ErrorKind::BadInput) << e.what();
    const auto expected = kRefused.find(name);
    EXPECT_NE(expected, kRefused.end()) << name << " was refused: " << e.what();
    if (expected != kRefused.end())
      EXPECT_NE(std::string(e.what()).find(expected->second), std::string::npos) << e.what();
    std::cout << "[occt-misc] " << name << ": refused (" << e.what() << ")\n";
    RecordProperty("refused", e.what());
    return;
  }
  EXPECT_EQ(kRefused.count(name), 0u) << name << " should have been refused";
  const double readMs = msSince(start);
  const bool brep = model.kind == SourceKind::Brep;
  int solids = 0;
  for (TopExp_Explorer it(model.shape, TopAbs_SOLID); it.More(); it.Next()) ++solids;
  const int meshPlanes = 8, exactPlanes = 4;

  double meshMs = 0, exactMs = 0;
  std::ostringstream areas;
  double total = 0;  // some plane must meet a closed solid (thin panels may slip between
                     // the planes of one direction: MODERN_Sink_1_opened along X)
  for (const Vec3& dir : {Vec3{1, 0, 0}, Vec3{0, 1, 0}}) {
    const SliceFrame frame = makeSliceFrame(dir, {0, 0, 1});
    const Interval range = model.mesh.extent(frame.normal);
    start = std::chrono::steady_clock::now();
    const SliceSet set = sliceMesh(model.mesh, frame, uniformPositions(range.lo, range.hi, meshPlanes));
    meshMs += msSince(start);
    for (const Slice& s : set.slices) total += s.region.area();
    if (!brep) continue;

    // Exact sections at four planes, compared with mesh sections at the same planes.
    const std::vector<double> positions = uniformPositions(range.lo, range.hi, exactPlanes);
    const double deflection = exactDeflection(model.meshDeflection);  // as the CLI does
    start = std::chrono::steady_clock::now();
    const std::vector<ExactSlice> exact = sliceBrep(model.shape, frame, positions, deflection);
    exactMs += msSince(start);
    const SliceSet mesh = sliceMesh(model.mesh, frame, positions);
    double largest = 0;
    for (const ExactSlice& s : exact) largest = std::max(largest, s.area);
    for (size_t i = 0; i < exact.size(); ++i) {
      SCOPED_TRACE(dir.x == 1 ? "along x" : "along y");
      // The mesh slicer unites overlapping solids; ExactSlice::area counts their overlap
      // twice, its region does not. The region is within the polygon deflection of the faces.
      const double m = mesh.slices[i].region.area(), x = exact[i].area, u = exact[i].region.area();
      EXPECT_GE(x, 0.0);
      const double polygonError = exact[i].faces.IsNull() ? 0 : perimeter(exact[i].faces) * deflection + 1e-6;
      EXPECT_LE(u, x + polygonError) << "at " << positions[i];
      if (solids == 1) {
        EXPECT_NEAR(u, x, polygonError) << "at " << positions[i];
      }
      expectAgreement(model, frame, positions[i], m, u, 0.02 * largest + 1.0, deflection);
      areas << " " << m << "/" << x;
    }
  }
  EXPECT_GT(total, 0.0) << "no plane meets this closed solid";
  const double meshPerSlice = meshMs / (2 * meshPlanes);
  const double exactPerSlice = brep ? exactMs / (2 * exactPlanes) : 0;
  std::cout << "[occt-misc] " << name << ": " << model.mesh.triangles.size() << " triangles, read " << readMs
            << " ms, mesh " << meshPerSlice << " ms/slice";
  if (brep) std::cout << ", exact " << exactPerSlice << " ms/slice; mesh/exact areas" << areas.str();
  std::cout << "\n";
  RecordProperty("triangles", std::to_string(model.mesh.triangles.size()));
  RecordProperty("read_ms", std::to_string(readMs));
  RecordProperty("mesh_ms_per_slice", std::to_string(meshPerSlice));
  if (brep) RecordProperty("exact_ms_per_slice", std::to_string(exactPerSlice));
}

INSTANTIATE_TEST_SUITE_P(OcctMisc, OcctSample, testing::ValuesIn(sampleFiles()), testName);

}  // namespace
}  // namespace sliceform

namespace sliceform {
namespace {

// Every exact section edge of occt-misc Bottom.brep, sampled by sampleEdge, lies within
// its deflection of the polygon, checked at 64 parameters per chord. OCCT's
// GCPnts_QuasiUniformDeflection alone gives chords up to 0.20 mm off these B-splines (only
// C1: degree 8, knots of multiplicity 7) on the planes across Y, ten times the deflection (in
// a design's section of the same part, a whole edge as one chord 1.27 mm off). Across X, a
// chord whose middle lay on its curve was 0.26 mm off it nearer an end.
TEST(EdgeSamples, SectionCurvesLieWithinTheDeflection) {
  const std::string path = kData + "/occ/Bottom.brep";
  if (!fs::exists(path)) GTEST_SKIP() << path << " is missing";
  const Model model = readModel(path);
  const double deflection = 0.02;
  int edges = 0, worst = 0;
  double farthest = 0;
  for (const Vec3 normal : {Vec3{0, 1, 0}, Vec3{1, 0, 0}}) {
    const SliceFrame frame = makeSliceFrame(normal);
    const Interval range = model.mesh.extent(frame.normal);
    std::vector<double> positions;
    for (int k = 1; k < 24; ++k) positions.push_back(range.lo + (range.hi - range.lo) * k / 24);
    for (const ExactSlice& slice :
         sliceBrep(model.shape, frame, positions, deflection, SliceDetail::FacesOnly))
      for (TopExp_Explorer e(slice.faces, TopAbs_EDGE); e.More(); e.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
        const CurveSamples s = sampleEdge(edge, deflection);
        ASSERT_GE(s.p.size(), 2u);
        ++edges;
        const BRepAdaptor_Curve curve(edge);
        for (size_t i = 0; i + 1 < s.t.size(); ++i) {
          const gp_Vec chord(s.p[i], s.p[i + 1]);
          for (int k = 1; k < 64; ++k) {
            const gp_Pnt q = curve.Value(s.t[i] + (s.t[i + 1] - s.t[i]) * k / 64);
            const gp_Vec aq(s.p[i], q);
            const double f = chord.SquareMagnitude() > 0
                                 ? std::clamp(aq.Dot(chord) / chord.SquareMagnitude(), 0.0, 1.0)
                                 : 0.0;
            const double off = (aq - chord * f).Magnitude();
            if (off > farthest) farthest = off;
            worst += off > 2 * deflection;
          }
        }
      }
  }
  EXPECT_GT(edges, 200);
  EXPECT_EQ(worst, 0) << "farthest " << farthest << " mm";
}

}  // namespace
}  // namespace sliceform
