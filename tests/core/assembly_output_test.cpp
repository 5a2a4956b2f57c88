// SPDX-License-Identifier: LGPL-2.1-or-later
// The 3D outputs of the assembled sliceform: the binary glTF (header, metres, Y up, bounds,
// two-sided colours) and the software-rendered picture (size, paper colours, same poses as
// the exact assembly).
#include <gtest/gtest.h>

#include <cairo.h>
#include <jpeglib.h>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include "arrangement/arrange.hpp"
#include "assembly/fold.hpp"
#include "exact/patch_faces.hpp"
#include "output/assembly_png.hpp"
#include "output/gltf.hpp"
#include "output/jpeg.hpp"
#include "output/png_file.hpp"
#include "realization/realize.hpp"
#include "support/error.hpp"
#include "support/plane_curves.hpp"
#include "test_support.hpp"

namespace sliceform {
namespace {

struct Design {
  Arrangement arrangement;
  std::vector<PatchFace> faces;
};

// A torus: both families, and patches with holes (the even-odd fill must keep them open). Its
// triangulation rather than the exact solid: the polygon path is 25 times faster.
const Design& torus() {
  static const Design d = [] {
    const Model model = modelFromMesh(modelFromShape(test::makeTorus(60, 20), "torus").mesh, "torus mesh");
    ArrangementParams params;
    params.slices = 24;
    params.hinges.slotWidth = SlotParams{}.width();
    Design out;
    out.arrangement = arrange(model, params);
    const Realization r = realize(realizationInput(out.arrangement, model.meshDeflection), SlotParams{});
    out.faces = exactPatches(model, out.arrangement, r);
    return out;
  }();
  return d;
}

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

uint32_t le32(const std::string& bytes, size_t at) {
  uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;  // the test machines are little-endian, like the format
}

// The exact bounds of a shape in mm.
Bnd_Box bounds(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::AddOptimal(shape, box, /*useTriangulation=*/false, /*useShapeTolerance=*/false);
  return box;
}

TEST(AssemblyOutput, GlbIsInMetresWithYUpAndTheAssemblysBounds) {
  const Design& d = torus();
  const TopoDS_Shape all = assemble(d.arrangement, d.faces, 40);
  const std::vector<Panel3> panels = assemblyPanels(d.arrangement, d.faces, 40);
  test::TempDir dir;
  const std::string path = dir.file("torus.glb");
  writeGltf(panels, path);

  // The 12-byte header and the JSON chunk (glTF 2.0, "Binary glTF Layout").
  const std::string bytes = readAll(path);
  ASSERT_GT(bytes.size(), 20u);
  EXPECT_EQ(bytes.substr(0, 4), "glTF");
  EXPECT_EQ(le32(bytes, 4), 2u);
  EXPECT_EQ(le32(bytes, 8), bytes.size());
  const uint32_t jsonLength = le32(bytes, 12);
  ASSERT_EQ(le32(bytes, 16), 0x4E4F534Au);  // "JSON"
  ASSERT_LE(20 + jsonLength + 8, bytes.size());
  EXPECT_EQ(le32(bytes, 20 + jsonLength + 4), 0x004E4942u);  // then "BIN\0"
  const nlohmann::json gltf = nlohmann::json::parse(bytes.substr(20, jsonLength));

  // One mesh per patch; no node moves anything, so the accessors' bounds are the model's.
  ASSERT_TRUE(gltf.contains("meshes"));
  EXPECT_EQ(gltf["meshes"].size(), panels.size());
  for (const auto& node : gltf["nodes"]) {
    EXPECT_FALSE(node.contains("matrix") || node.contains("translation") || node.contains("rotation") ||
                 node.contains("scale"));
  }
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const auto& mesh : gltf["meshes"])
    for (const auto& primitive : mesh["primitives"]) {
      const auto& accessor = gltf["accessors"][primitive["attributes"]["POSITION"].get<int>()];
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], accessor["min"][k].get<double>());
        hi[k] = std::max(hi[k], accessor["max"][k].get<double>());
      }
    }
  // Our (x, y, z) in mm is glTF's (x, z, -y) in metres.
  double x0, y0, z0, x1, y1, z1;
  bounds(all).Get(x0, y0, z0, x1, y1, z1);
  const double wantLo[3] = {x0 / 1000, z0 / 1000, -y1 / 1000}, wantHi[3] = {x1 / 1000, z1 / 1000, -y0 / 1000};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(lo[k], wantLo[k], 1e-4) << "axis " << k;
    EXPECT_NEAR(hi[k], wantHi[k], 1e-4) << "axis " << k;
  }

  // Paper is seen from both sides and is not metal (glTF's default metallicFactor is 1); the
  // two families have two colours.
  std::set<std::vector<double>> colours;
  ASSERT_TRUE(gltf.contains("materials"));
  for (const auto& material : gltf["materials"]) {
    EXPECT_TRUE(material.value("doubleSided", false));
    const auto& pbr = material["pbrMetallicRoughness"];
    EXPECT_EQ(pbr.value("metallicFactor", 1.0), 0.0);
    colours.insert(pbr["baseColorFactor"].get<std::vector<double>>());
  }
  EXPECT_EQ(colours.size(), 2u);

  // The triangles cover the outlines exactly: their area is the panels' (even-odd) area.
  const size_t bin = 20 + jsonLength + 8;
  auto view = [&](int accessor) {
    const auto& a = gltf["accessors"][accessor];
    const auto& v = gltf["bufferViews"][a["bufferView"].get<int>()];
    return bin + v.value("byteOffset", 0) + a.value("byteOffset", 0);
  };
  double triangles = 0;
  for (const auto& mesh : gltf["meshes"])
    for (const auto& primitive : mesh["primitives"]) {
      const size_t points = view(primitive["attributes"]["POSITION"].get<int>());
      const auto& indices = gltf["accessors"][primitive["indices"].get<int>()];
      // Unsigned short or unsigned int indices, as the mesh needs.
      const int type = indices["componentType"].get<int>();
      ASSERT_TRUE(type == 5123 || type == 5125) << type;
      const size_t width = type == 5123 ? 2 : 4;
      auto point = [&](uint32_t i) {
        float p[3];
        std::memcpy(p, bytes.data() + points + 12 * i, 12);
        return Vec3{p[0], p[1], p[2]};
      };
      const size_t at = view(primitive["indices"].get<int>());
      auto index = [&](int k) {
        uint32_t i = 0;
        std::memcpy(&i, bytes.data() + at + width * k, width);
        return i;
      };
      for (int t = 0; t < indices["count"].get<int>(); t += 3) {
        const Vec3 a = point(index(t)), b = point(index(t + 1)), c = point(index(t + 2));
        triangles += 0.5 * norm(cross(b - a, c - a)) * 1e6;  // m² to mm²
      }
    }
  double outlines = 0;
  for (const PatchFace& f : d.faces) outlines += f.outline.area();
  EXPECT_NEAR(triangles, outlines, 1e-4 * outlines);
  // Nothing is left beside the file: no temporary .glb, no side .bin.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.file("")), {}), 1);
}

// The 2D B-spline curve of the first face's first edge that has one, and its range.
Handle(Geom2d_BSplineCurve) planeBSpline(const TopoDS_Shape& shape, double& first, double& last) {
  const TopoDS_Face f = TopoDS::Face(TopExp_Explorer(shape, TopAbs_FACE).Current());
  for (TopExp_Explorer e(f, TopAbs_EDGE); e.More(); e.Next())
    if (auto c = Handle(Geom2d_BSplineCurve)::DownCast(
            BRep_Tool::CurveOnSurface(TopoDS::Edge(e.Current()), f, first, last)))
      return c;
  return Handle(Geom2d_BSplineCurve)();
}

// The face bounded by `curve` on [from, to] and the straight edge back, given to
// withPlaneCurves trimmed and not: the trimmed 2D curve spans the edge's range and no more,
// runs where the whole one does, and the face given keeps no 2D curves. The whole curve,
// as the projection makes it.
Handle(Geom2d_BSplineCurve)
    expectTrimmedToTheEdge(const Handle(Geom_BSplineCurve) & curve, double from, double to) {
  const TopoDS_Edge curved = BRepBuilderAPI_MakeEdge(curve, from, to);
  const TopoDS_Edge straight = BRepBuilderAPI_MakeEdge(curve->Value(to), curve->Value(from));
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(curved, straight).Wire(), true);
  EXPECT_FALSE(face.IsNull());
  double first = 0, last = 0, whole0 = 0, whole1 = 0;
  const Handle(Geom2d_BSplineCurve) trimmed = planeBSpline(withPlaneCurves(face, true), first, last);
  const Handle(Geom2d_BSplineCurve) whole = planeBSpline(withPlaneCurves(face), whole0, whole1);
  if (trimmed.IsNull() || whole.IsNull()) {
    ADD_FAILURE() << "no 2D B-spline curve";
    return whole;
  }
  EXPECT_NEAR(first, from, 1e-12);
  EXPECT_NEAR(last, to, 1e-12);
  EXPECT_FALSE(trimmed->IsPeriodic());
  EXPECT_NEAR(trimmed->FirstParameter(), from, 1e-9);
  EXPECT_NEAR(trimmed->LastParameter(), to, 1e-9);
  for (int k = 0; k <= 12; ++k) {
    const double t = from + (to - from) * k / 12;
    EXPECT_LT(trimmed->Value(t).Distance(whole->Value(t)), 1e-9) << t;
  }
  // The face given is left as it was: a plane's face stores no 2D curves.
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
    Standard_Boolean stored = Standard_True;
    BRep_Tool::CurveOnSurface(TopoDS::Edge(e.Current()), face, first, last, &stored);
    EXPECT_FALSE(stored);
  }
  return whole;
}

// The STEP writer bounds a face's 2D curves once for every edge of it (withPlaneCurves):
// a B-spline curve longer than its edge is cut to the edge's range there, where bounding it
// would copy and cut it every time. An arch: a cubic B-spline from (0,0) to (30,0) through
// (10,20) and (20,20), its middle (parameters 0.2 to 0.8) closed by a straight edge.
TEST(AssemblyOutput, PlaneCurvesAreTrimmedToTheirEdges) {
  TColgp_Array1OfPnt poles(1, 4);
  poles(1) = {0, 0, 0}, poles(2) = {10, 20, 0}, poles(3) = {20, 20, 0}, poles(4) = {30, 0, 0};
  TColStd_Array1OfReal knots(1, 2);
  knots(1) = 0, knots(2) = 1;
  TColStd_Array1OfInteger mults(1, 2);
  mults(1) = mults(2) = 4;
  const Handle(Geom2d_BSplineCurve) whole =
      expectTrimmedToTheEdge(new Geom_BSplineCurve(poles, knots, mults, 3), 0.2, 0.8);
  ASSERT_FALSE(whole.IsNull());
  EXPECT_NEAR(whole->FirstParameter(), 0, 1e-12);  // as the projection makes it
  EXPECT_NEAR(whole->LastParameter(), 1, 1e-12);
}

// A piece of a closed curve (a section's loop between two slots): a periodic cubic
// B-spline through eight points round a circle, its edge the parameters 1 to 4 (of 8).
// Its 2D curve is cut to the edge's range once, no longer periodic; the whole loop, an edge
// of its own, keeps its periodic curve.
TEST(AssemblyOutput, PiecesOfClosedPlaneCurvesAreTrimmedToTheirEdges) {
  TColgp_Array1OfPnt poles(1, 8);
  for (int k = 0; k < 8; ++k) poles(k + 1) = {20 * std::cos(M_PI * k / 4), 20 * std::sin(M_PI * k / 4), 0};
  TColStd_Array1OfReal knots(1, 9);
  TColStd_Array1OfInteger mults(1, 9);
  for (int k = 0; k < 9; ++k) knots(k + 1) = k, mults(k + 1) = 1;
  const Handle(Geom_BSplineCurve) loop = new Geom_BSplineCurve(poles, knots, mults, 3, Standard_True);
  ASSERT_TRUE(loop->IsPeriodic());
  const Handle(Geom2d_BSplineCurve) whole = expectTrimmedToTheEdge(loop, 1, 4);
  ASSERT_FALSE(whole.IsNull());
  EXPECT_TRUE(whole->IsPeriodic());  // as the projection makes it
  // The whole loop as one edge: nothing to cut.
  const TopoDS_Face disc =
      BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(loop)).Wire(), true);
  ASSERT_FALSE(disc.IsNull());
  double first = 0, last = 0;
  const Handle(Geom2d_BSplineCurve) round = planeBSpline(withPlaneCurves(disc, true), first, last);
  ASSERT_FALSE(round.IsNull());
  EXPECT_TRUE(round->IsPeriodic());
}

TEST(AssemblyOutput, GltfErrorsAreIoErrors) {
  const Design& d = torus();
  test::TempDir dir;
  try {
    writeGltf(assemblyPanels(d.arrangement, d.faces, 90), dir.file("missing/folder/a.glb"));
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Io);
    // The message names the file the user asked for, not a temporary one.
    EXPECT_NE(std::string(e.what()).find("folder/a.glb:"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("a.glb.tmp"), std::string::npos) << e.what();
  }
}

// The panels are where assemble() puts the exact faces, folded or not.
TEST(AssemblyOutput, PanelsHaveTheAssemblysPoses) {
  const Design& d = torus();
  for (double theta : {90.0, 25.0}) {
    const std::vector<Panel3> panels = assemblyPanels(d.arrangement, d.faces, theta);
    // One per patch with faces, in order, with its family.
    std::vector<int> families;
    for (size_t k = 0; k < d.faces.size(); ++k)
      if (!d.faces[k].shape.IsNull())
        families.push_back(d.arrangement.scaffold.patches[k].family == Family::U ? 0 : 1);
    ASSERT_EQ(panels.size(), families.size());
    for (size_t k = 0; k < panels.size(); ++k) EXPECT_EQ(panels[k].family, families[k]);
    Box3 box;
    double offPlane = 0;  // every point lies on its panel's plane, whose normal is given
    for (const Panel3& p : panels)
      for (const auto& loop : p.loops)
        for (const Vec3& q : loop) {
          box.add(q);
          offPlane = std::max(offPlane, std::fabs(dot(q - p.loops[0][0], p.normal)));
        }
    EXPECT_LT(offPlane, 1e-9) << theta;
    double x0, y0, z0, x1, y1, z1;
    bounds(assemble(d.arrangement, d.faces, theta)).Get(x0, y0, z0, x1, y1, z1);
    const double tolerance = 2 * kOutlineDeflection + 1e-3;
    EXPECT_NEAR(box.min.x, x0, tolerance) << theta;
    EXPECT_NEAR(box.min.y, y0, tolerance) << theta;
    EXPECT_NEAR(box.min.z, z0, tolerance) << theta;
    EXPECT_NEAR(box.max.x, x1, tolerance) << theta;
    EXPECT_NEAR(box.max.y, y1, tolerance) << theta;
    EXPECT_NEAR(box.max.z, z1, tolerance) << theta;
  }
}

TEST(AssemblyOutput, PictureShowsBothPaperColours) {
  const Design& d = torus();
  test::TempDir dir;
  const std::string path = dir.file("torus.png");
  writeAssemblyPng(assemblyPanels(d.arrangement, d.faces, 60), path, 400);

  cairo_surface_t* image = cairo_image_surface_create_from_png(path.c_str());
  ASSERT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
  const int w = cairo_image_surface_get_width(image), h = cairo_image_surface_get_height(image);
  EXPECT_EQ(w, 400);
  EXPECT_GT(h, 100);
  EXPECT_LE(h, 600);
  const unsigned char* data = cairo_image_surface_get_data(image);
  const int stride = cairo_image_surface_get_stride(image);
  int paper = 0, warm = 0, cool = 0, dark = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint32_t p = reinterpret_cast<const uint32_t*>(data + y * stride)[x];
      const int r = p >> 16 & 255, g = p >> 8 & 255, b = p & 255;
      if (r + g + b < 3 * 100) ++dark;
      if (r == 255 && g == 255 && b == 255) continue;
      ++paper;
      if (r > b + 25) ++warm;  // the U paper, cream
      if (b > r + 25) ++cool;  // the V paper, blue
    }
  cairo_surface_destroy(image);
  const double pixels = static_cast<double>(w) * h;
  EXPECT_GT(paper / pixels, 0.15);
  EXPECT_GT(warm / pixels, 0.03);
  EXPECT_GT(cool / pixels, 0.03);
  EXPECT_GT(dark / pixels, 0.005) << "edge lines";
}

// What a PNG file holds, read back by cairo: 0x00RRGGBB a pixel, row by row.
Picture readPng(const std::string& path) {
  cairo_surface_t* image = cairo_image_surface_create_from_png(path.c_str());
  EXPECT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
  Picture out;
  out.width = cairo_image_surface_get_width(image), out.height = cairo_image_surface_get_height(image);
  const unsigned char* data = cairo_image_surface_get_data(image);
  const int stride = cairo_image_surface_get_stride(image);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      out.pixels.push_back(reinterpret_cast<const uint32_t*>(data + y * stride)[x] & 0xFFFFFF);
  cairo_surface_destroy(image);
  return out;
}

// The PNG files are written by libpng with one row filter and a fast level (png_file.cpp):
// pixel for pixel the picture, whatever the row stride.
TEST(AssemblyOutput, PngFilesHoldThePicturePixelForPixel) {
  test::TempDir dir;
  const Picture drawn = drawAssembly(assemblyPanels(torus().arrangement, torus().faces, 60), 300);
  writePicturePng(drawn, dir.file("torus.png"));
  const Picture read = readPng(dir.file("torus.png"));
  EXPECT_EQ(read.width, drawn.width);
  EXPECT_EQ(read.height, drawn.height);
  EXPECT_TRUE(read.pixels == drawn.pixels);
  // Rows three pixels longer than the picture (a cairo surface's stride), every channel
  // value in every position.
  const int w = 61, h = 37, stride = w + 3;
  std::vector<uint32_t> pixels(static_cast<size_t>(stride) * h, 0xFF000000);
  std::vector<uint32_t> expected;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint32_t c = static_cast<uint32_t>((x * 4 + y) & 255) << 16 |
                         static_cast<uint32_t>(255 - x * 3) << 8 | static_cast<uint32_t>(y * 7);
      pixels[static_cast<size_t>(y) * stride + x] = c;
      expected.push_back(c);
    }
  writeRgbPng(dir.file("strided.png"), pixels.data(), w, h, stride);
  const Picture strided = readPng(dir.file("strided.png"));
  EXPECT_EQ(strided.width, w);
  EXPECT_EQ(strided.height, h);
  EXPECT_TRUE(strided.pixels == expected);
  EXPECT_THROW(writeRgbPng(dir.file("missing/a.png"), pixels.data(), w, h, stride), Error);
}

// Channels of two 0x00RRGGBB colours differ by more than `tolerance`.
bool differ(uint32_t a, uint32_t b, int tolerance) {
  for (int shift = 0; shift <= 16; shift += 8)
    if (std::abs(int(a >> shift & 255) - int(b >> shift & 255)) > tolerance) return true;
  return false;
}

// The booklet's step pictures redraw only the new panel's box: after every panel is
// added, the picture is the whole assembly's but for the last panel, which is highlighted.
// A box kept stale (a panel missing, an outline lost) shows as many more pixels apart.
TEST(AssemblyOutput, GrowingAssemblyEndsAsTheWholePicture) {
  const Design& d = torus();
  const std::vector<Panel3> panels = assemblyPanels(d.arrangement, d.faces, 60);
  ASSERT_GT(panels.size(), 10u);
  const Picture whole = drawAssembly(panels, 300);
  GrowingAssembly growing(panels, 300);
  std::vector<Picture> steps;
  for (size_t k = 0; k < panels.size(); ++k) steps.push_back(growing.add(static_cast<int>(k)));
  const Picture& last = steps.back();
  ASSERT_EQ(last.width, whole.width);
  ASSERT_EQ(last.height, whole.height);
  size_t apart = 0, highlight = 0;
  for (size_t at = 0; at < whole.pixels.size(); ++at) {
    if (!differ(last.pixels[at], kHighlight, 60))
      ++highlight;
    else if (differ(last.pixels[at], whole.pixels[at], 40))
      ++apart;
  }
  EXPECT_GT(highlight, 50u);
  EXPECT_LT(apart, whole.pixels.size() / 100) << "of " << whole.pixels.size();
  // Each step adds to the one before: a pixel of paper stays paper (or its outline).
  for (size_t k = 1; k < steps.size(); ++k) {
    size_t lost = 0;
    for (size_t at = 0; at < whole.pixels.size(); ++at)
      if (steps[k - 1].pixels[at] != 0xFFFFFF && steps[k].pixels[at] == 0xFFFFFF) ++lost;
    EXPECT_EQ(lost, 0u) << "step " << k;
  }
}

// The booklet's pictures go into its PDF as JPEG: the bytes decode (with libjpeg) to the
// picture's size and colours.
TEST(AssemblyOutput, JpegDecodesToThePicture) {
  Picture p;
  p.width = 64;
  p.height = 40;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) p.pixels.push_back(x < 32 ? kHighlight : 0xFFFFFF);
  const std::string bytes = jpegBytes(p, 85);
  ASSERT_GT(bytes.size(), 4u);
  EXPECT_EQ(static_cast<unsigned char>(bytes[0]), 0xFF);
  EXPECT_EQ(static_cast<unsigned char>(bytes[1]), 0xD8);  // start of image
  jpeg_decompress_struct info{};
  jpeg_error_mgr error{};
  info.err = jpeg_std_error(&error);
  jpeg_create_decompress(&info);
  jpeg_mem_src(&info, reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
  ASSERT_EQ(jpeg_read_header(&info, TRUE), JPEG_HEADER_OK);
  jpeg_start_decompress(&info);
  EXPECT_EQ(int(info.output_width), p.width);
  EXPECT_EQ(int(info.output_height), p.height);
  ASSERT_EQ(info.output_components, 3);
  std::vector<unsigned char> row(info.output_width * 3);
  int wrong = 0;
  while (info.output_scanline < info.output_height) {
    JSAMPROW rows[1] = {row.data()};
    jpeg_read_scanlines(&info, rows, 1);
    for (int x = 0; x < p.width; ++x) {
      const uint32_t got = uint32_t(row[3 * x]) << 16 | uint32_t(row[3 * x + 1]) << 8 | row[3 * x + 2];
      if (differ(got, x < 32 ? kHighlight : 0xFFFFFF, 12)) ++wrong;
    }
  }
  jpeg_finish_decompress(&info);
  jpeg_destroy_decompress(&info);
  EXPECT_EQ(wrong, 0);
  Picture empty;
  EXPECT_THROW(jpegBytes(empty, 85), Error);
}

TEST(AssemblyOutput, PictureRejectsNothingToDrawAndBadFolders) {
  test::TempDir dir;
  EXPECT_THROW(writeAssemblyPng({}, dir.file("a.png")), Error);
  EXPECT_FALSE(std::filesystem::exists(dir.file("a.png")));
  const Design& d = torus();
  try {
    writeAssemblyPng(assemblyPanels(d.arrangement, d.faces, 90), dir.file("missing/a.png"), 200);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Io);
  }
}

}  // namespace
}  // namespace sliceform
