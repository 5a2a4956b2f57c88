// SPDX-License-Identifier: LGPL-2.1-or-later
// Model reading: OCCT sample files, OFF files, and every way a file can be unusable.
#include <gtest/gtest.h>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <gp_Pln.hxx>

#include <cmath>
#include <random>

#include "model/model.hpp"
#include "slicing/mesh_slicer.hpp"
#include "support/error.hpp"
#include "test_support.hpp"

namespace sliceform {
namespace {

const std::string kData = SLICEFORM_OCCT_DATA_DIR;

// Runs fn, which must throw Error of kind BadInput whose message holds `fragment`.
template <class Fn>
void expectBadInput(Fn&& fn, const std::string& fragment) {
  try {
    fn();
    ADD_FAILURE() << "no error; expected one mentioning \"" << fragment << "\"";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

void expectUsable(const Model& m, SourceKind kind) {
  EXPECT_EQ(m.kind, kind);
  EXPECT_GT(m.mesh.triangles.size(), 0u);
  EXPECT_FALSE(m.bounds.empty());
  EXPECT_GT(m.bounds.diagonal(), 0.0);
  if (kind == SourceKind::Brep) {
    EXPECT_FALSE(m.shape.IsNull());
    // The default deflection is 1/1000 of the diagonal.
    EXPECT_NEAR(m.meshDeflection, 1e-3 * m.bounds.diagonal(), 1e-12 * m.bounds.diagonal());
    EXPECT_TRUE(TopExp_Explorer(m.shape, TopAbs_SOLID).More());
  } else {
    EXPECT_TRUE(m.shape.IsNull());
  }
  // The mesh lies in the shape's box (up to the deflection).
  const Box3 mb = m.mesh.bounds();
  const double slack = m.meshDeflection + 1e-9 * m.bounds.diagonal();
  EXPECT_GE(mb.min.x, m.bounds.min.x - slack);
  EXPECT_LE(mb.max.z, m.bounds.max.z + slack);
}

TEST(Model, ReadsOcctSampleFiles) {
  if (!std::filesystem::is_directory(kData)) GTEST_SKIP() << kData << " is not installed";
  const Model ball = readModel(kData + "/occ/Ball.brep");
  expectUsable(ball, SourceKind::Brep);
  EXPECT_NO_THROW(requireClosed(ball));
  const Model screw = readModel(kData + "/step/screw.step");
  expectUsable(screw, SourceKind::Brep);
  EXPECT_NO_THROW(requireClosed(screw));
  // The IGES bearing is 213 trimmed surfaces and no solid: readable, but not a solid.
  expectBadInput([&] { readModel(kData + "/iges/bearing.iges"); }, "no closed solid");
  // The STL bearing reads as a welded mesh; it has two holes, so it cannot be sliced.
  const Model stl = readModel(kData + "/stl/bearing.stl");
  expectUsable(stl, SourceKind::Mesh);
  EXPECT_EQ(stl.meshDeflection, 0.0);
  EXPECT_EQ(stl.source, kData + "/stl/bearing.stl");
  // Welding found the shared corners: far fewer vertices than 3 per triangle.
  EXPECT_LT(stl.mesh.vertices.size(), stl.mesh.triangles.size());
  expectBadInput([&] { requireClosed(stl); }, "not closed");
}

// A model's bounds are OCCT's optimal box of its geometry, to the bit, though the search is
// run only on the faces that may reach a side (model.cpp, exactBounds): free-form and
// curved parts, one whose edges claim 0.5 mm, and occt-misc parts with loose tolerances
// (MODERN_Sink_1: 3 mm) and with most of their faces inside (Bottom, Top).
TEST(Model, BoundsAreTheOptimalBoxOfTheGeometry) {
  const auto expectOptimal = [](const Model& m) {
    SCOPED_TRACE(m.source);
    Bnd_Box box;
    BRepBndLib::AddOptimal(m.shape, box, Standard_False);
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    EXPECT_EQ(m.bounds.min.x, x0);
    EXPECT_EQ(m.bounds.min.y, y0);
    EXPECT_EQ(m.bounds.min.z, z0);
    EXPECT_EQ(m.bounds.max.x, x1);
    EXPECT_EQ(m.bounds.max.y, y1);
    EXPECT_EQ(m.bounds.max.z, z1);
  };
  const TopoDS_Shape loose = test::makeTorus(10, 3);
  test::loosen(loose, 0.5);
  for (const TopoDS_Shape& shape : {test::loft(), test::boredLoft(), test::makeTorus(10, 3), loose,
                                    test::makeBoxWithHoles(40, 30, 20, {{10, 10, 4}, {28, 18, 6}})})
    expectOptimal(modelFromShape(shape, "test solid"));
  if (!std::filesystem::is_directory(kData)) GTEST_SKIP() << kData << " is not installed";
  for (const char* part : {"Bottom.brep", "Top.brep", "MODERN_Sink_1.brep", "Ball.brep"})
    expectOptimal(readModel(kData + "/occ/" + part));
}

// Edges of `shape` used by a single face (seams and degenerate edges excepted).
int freeEdges(const TopoDS_Shape& shape) {
  TopTools_IndexedDataMapOfShapeListOfShape faces;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, faces);
  int count = 0;
  for (int i = 1; i <= faces.Extent(); ++i) {
    const TopoDS_Edge& edge = TopoDS::Edge(faces.FindKey(i));
    if (BRep_Tool::Degenerated(edge) || faces(i).Extent() != 1) continue;
    if (!BRep_Tool::IsClosed(edge, TopoDS::Face(faces(i).First()))) ++count;
  }
  return count;
}

TEST(Model, ClosedSolidWithLocatedFacesGivesAClosedMesh) {
  // CrankArm.brep is a valid closed solid whose faces all carry locations (placements).
  // Moving the same edge node with two faces' locations can round differently; the mesh
  // must still be welded along every shared edge.
  const std::string path = kData + "/occ/CrankArm.brep";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is not installed";
  const Model m = readModel(path);
  ASSERT_EQ(freeEdges(m.shape), 0);
  int located = 0;
  for (TopExp_Explorer it(m.shape, TopAbs_FACE); it.More(); it.Next())
    located += !it.Current().Location().IsIdentity();
  ASSERT_GT(located, 0);
  EXPECT_NO_THROW(requireClosed(m)) << analyseTopology(m.mesh).describe();
}

TEST(Model, TouchingSolidsAreEachClosed) {
  // Two boxes sharing the face x = 10 (as geometry, not as topology): their corners
  // coincide, yet each is a closed solid and the model must be usable.
  BRep_Builder builder;
  TopoDS_Compound pair;
  builder.MakeCompound(pair);
  builder.Add(pair, BRepPrimAPI_MakeBox(10, 10, 10).Shape());
  builder.Add(pair, BRepPrimAPI_MakeBox(gp_Pnt(10, 0, 0), 10, 10, 10).Shape());
  const Model m = modelFromShape(pair, "pair", 0.01);
  EXPECT_NO_THROW(requireClosed(m)) << analyseTopology(m.mesh).describe();
  // Sliced across the common face, the two sections unite into one rectangle.
  const SliceSet set = sliceMesh(m.mesh, makeSliceFrame({0, 0, 1}), {5});
  EXPECT_NEAR(set.slices[0].region.area(), 200, 1e-9);
  EXPECT_EQ(set.slices[0].region.components().size(), 1u);
}

TEST(Model, ReadsOffTetrahedron) {
  test::TempDir dir;
  const std::string path = dir.write("tetra.off",
                                     "OFF\n"
                                     "# a unit corner tetrahedron\n"
                                     "4 4 6\n"
                                     "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                                     "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const Model m = readModel(path);
  EXPECT_EQ(m.kind, SourceKind::Mesh);
  ASSERT_EQ(m.mesh.vertices.size(), 4u);
  ASSERT_EQ(m.mesh.triangles.size(), 4u);
  EXPECT_EQ(m.mesh.vertices[3], (Vec3{0, 0, 1}));
  EXPECT_NO_THROW(requireClosed(m));
  EXPECT_EQ(m.bounds.max, (Vec3{1, 1, 1}));
  // The section at height h is the right triangle of legs 1 - h.
  const SliceSet set = sliceMesh(m.mesh, makeSliceFrame({0, 0, 1}), {0.25, 0.5});
  for (const Slice& s : set.slices)
    EXPECT_NEAR(s.region.area(), (1 - s.position) * (1 - s.position) / 2, 1e-9);
}

TEST(Model, ReadsOffQuadAsTwoTriangles) {
  // A square pyramid: base [0,2]² (a quad, listed facing down) and apex (1, 1, 3).
  test::TempDir dir;
  const std::string path = dir.write("pyramid.off",
                                     "OFF 5 5 8\n"
                                     "0 0 0\n2 0 0\n2 2 0\n0 2 0\n1 1 3\n"
                                     "4 0 3 2 1\n"
                                     "3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4  # last face\n");
  const Mesh raw = readOff(path);
  ASSERT_EQ(raw.triangles.size(), 6u);
  // The quad is fanned from its first corner.
  EXPECT_EQ(raw.triangles[0], (std::array<uint32_t, 3>{0, 3, 2}));
  EXPECT_EQ(raw.triangles[1], (std::array<uint32_t, 3>{0, 2, 1}));
  const Model m = readModel(path);
  EXPECT_NO_THROW(requireClosed(m));
  const SliceSet set = sliceMesh(m.mesh, makeSliceFrame({0, 0, 1}), {0.6, 1.5, 2.7});
  for (const Slice& s : set.slices) {
    const double side = 2 * (1 - s.position / 3);
    EXPECT_NEAR(s.region.area(), side * side, 1e-9);
  }
}

// The unit corner tetrahedron of ReadsOffTetrahedron, read whatever the OFF variant.
void expectCornerTetra(const std::string& path) {
  const Mesh raw = readOff(path);
  ASSERT_EQ(raw.vertices.size(), 4u);
  ASSERT_EQ(raw.triangles.size(), 4u);
  EXPECT_EQ(raw.vertices[1], (Vec3{1, 0, 0}));
  EXPECT_EQ(raw.vertices[3], (Vec3{0, 0, 1}));
  EXPECT_EQ(raw.triangles[3], (std::array<uint32_t, 3>{1, 2, 3}));
  EXPECT_NO_THROW(requireClosed(readModel(path)));
}

TEST(Model, ReadsEveryOffVariant) {
  // Vertex columns come in the order position, normal, colour, texture; faces may end in
  // a colour of 0 to 4 numbers (a colormap index, RGB or RGBA, integers or fractions).
  test::TempDir dir;
  const struct {
    const char* name;
    std::string content;
  } cases[] = {
      {"coff.off",
       "COFF\n4 4 6\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n0 0 1 128 128 128 255\n"
       "3 0 2 1 255 0 0\n3 0 1 3 0.5 0.5 0.5 1\n3 0 3 2 7\n3 1 2 3\n"},
      {"coff_rgb.off",
       "COFF 4 4 0\n0 0 0 1 0 0\n1 0 0 0 1 0\n0 1 0 0 0 1\n0 0 1 1 1 1\n"
       "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"},
      {"noff.off",
       "NOFF\n4 4 6\n0 0 0 -0.577 -0.577 -0.577\n1 0 0 1 0 0\n0 1 0 0 1 0\n0 0 1 0 0 1\n"
       "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"},
      {"cnoff.off",
       "CNOFF\n4 4 6\n0 0 0 -1 0 0 0.1 0.2 0.3 1\n1 0 0 1 0 0 0.1 0.2 0.3 1\n0 1 0 0 1 0 0.1 0.2 0.3 1\n"
       "0 0 1 0 0 1 0.1 0.2 0.3 1\n3 0 2 1 0 0 255\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"},
      {"stoff.off",
       "STOFF\n4 4 6\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n0 0 1 1 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"},
      {"stcnoff.off",
       "STCNOFF 4 4 6\n0 0 0 0 0 -1 1 1 1 1 0 0\n1 0 0 1 0 0 1 1 1 1 1 0\n0 1 0 0 1 0 1 1 1 1 0 1\n"
       "0 0 1 0 0 1 1 1 1 1 1 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"},
      // Geomview makes the keyword optional.
      {"no_keyword.off", "4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    expectCornerTetra(dir.write(c.name, c.content));
  }
}

TEST(Model, OffCommentsAndBlankLinesAnywhere) {
  test::TempDir dir;
  expectCornerTetra(dir.write("comments.off",
                              "# written by hand\n\nCOFF# the keyword, a comment straight after it\n"
                              "\n  # counts next\n\t4 4 6 # edges are not checked\n\n"
                              "0 0 0 # origin\r\n# between vertices\n1 0 0\n\n0 1 0 255 255 255\n0 0 1\n"
                              "\n# faces\n3 0 2 1 # no colour\n3 0 1 3 255 0 0 # a colour\n\n"
                              "3 0 3 2\n3 1 2 3\n# the end\n\n"));
}

TEST(Model, BadOffFilesAreBadInput) {
  test::TempDir dir;
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  const struct {
    const char* name;
    std::string content, fragment;
  } cases[] = {
      {"range.off", "OFF\n4 2 0\n" + vertices + "3 0 2 1\n3 0 1 7\n", "face 2 uses vertex 7, outside 0..3"},
      {"negative.off", "OFF\n4 1 0\n" + vertices + "3 0 -1 2\n", "uses vertex -1"},
      {"short_faces.off", "OFF\n4 4 0\n" + vertices + "3 0 2 1\n3 0 1 3\n", "ends after 2 of 4 faces"},
      {"short_vertices.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n", "ends after 2 of 4 vertices"},
      {"few_indices.off", "OFF\n4 1 0\n" + vertices + "4 0 1 2\n", "fewer indices"},
      {"two_gon.off", "OFF\n4 1 0\n" + vertices + "2 0 1\n", "fewer than 3 vertices"},
      {"bad_vertex.off", "OFF\n4 1 0\n0 0 0\n1 zero 0\n0 1 0\n0 0 1\n3 0 1 2\n", "vertex 2 is not three"},
      {"magic.off", "PLY\n4 1 0\n", "not an OFF file"},
      {"counts.off", "OFF\nfour faces\n", "cannot read the vertex and face counts"},
      {"huge.off", "OFF\n-4 1 0\n", "implausible counts"},
      {"comments.off", "# nothing but a comment\n", "empty"},
      // Line numbers count every line, comments and blank lines too.
      {"line.off", "OFF\n# c\n\n4 1 0\n" + vertices + "3 0 9 2\n", "line 9: face 1 uses vertex 9"},
      {"vertex_line.off", "COFF\n4 1 0\n0 0 0\n1 0\n", "line 4: vertex 2 is not three numbers"},
      {"colour.off", "OFF\n4 1 0\n" + vertices + "3 0 1 2 1 1 1 1 1\n", "line 7: face 1 has 5 numbers after"},
      {"colour_word.off", "OFF\n4 1 0\n" + vertices + "3 0 1 2 red\n", "line 7: face 1 ends in \"red\""},
      {"4off.off", "4OFF\n4 1 0\n", "line 1: 4OFF"},
      {"noff_dim.off", "nOFF\n3\n4 1 0\n", "line 1: nOFF"},
      {"binary.off", "OFF BINARY\n", "binary OFF"},
      {"keyword.off", "OFFICE\n4 1 0\n", "not an OFF file"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string path = dir.write(c.name, c.content);
    expectBadInput([&] { readModel(path); }, c.fragment);
    expectBadInput([&] { readModel(path); }, path);  // the message names the file
  }
}

TEST(Model, UnusableFilesAreBadInputNotCrashes) {
  test::TempDir dir;
  expectBadInput([&] { readModel(dir.write("empty.stl", "")); }, "empty");
  expectBadInput([&] { readModel(dir.write("empty.step", "")); }, "empty");
  expectBadInput([&] { readModel(dir.write("model.xyz", "1 2 3\n")); }, "unknown format \".xyz\"");
  expectBadInput([&] { readModel(dir.write("noext", "solid x\n")); }, "unknown format");
  expectBadInput([&] { readModel(dir.file("missing.stl")); }, "no such file");
  expectBadInput([&] { readModel(dir.file(".")); }, "no such file");  // a folder
  // Binary junk under every extension: a reader may refuse it, never crash on it.
  std::mt19937 random(12345);
  std::string junk(4096, '\0');
  for (char& c : junk) c = static_cast<char>(random() & 0xff);
  for (const char* ext : {".stl", ".obj", ".off", ".brep", ".step", ".iges"}) {
    SCOPED_TRACE(ext);
    expectBadInput([&] { readModel(dir.write(std::string("junk") + ext, junk)); }, "junk");
  }
  // Text that starts like an ASCII STL but holds no facets.
  expectBadInput([&] { readModel(dir.write("text.stl", "solid nothing\nendsolid nothing\n")); }, "text.stl");
}

TEST(Model, FaceOnlyBrepIsNotASolid) {
  test::TempDir dir;
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(gp_Pln(), -5, 5, -5, 5);
  const std::string path = dir.file("face.brep");
  ASSERT_TRUE(BRepTools::Write(face, path.c_str()));
  expectBadInput([&] { readModel(path); }, "no closed solid");
  expectBadInput([&] { readModel(path); }, "(1 face");
  expectBadInput([&] { modelFromShape(TopoDS_Shape(), "null shape"); }, "empty");
}

TEST(Model, ClosedShellBecomesASolidOpenShellDoesNot) {
  test::TempDir dir;
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(2, 3, 4).Shape();
  const TopoDS_Shell shell = TopoDS::Shell(TopExp_Explorer(box, TopAbs_SHELL).Current());
  const std::string closedPath = dir.file("shell.brep");
  ASSERT_TRUE(BRepTools::Write(shell, closedPath.c_str()));
  const Model m = readModel(closedPath);
  expectUsable(m, SourceKind::Brep);
  EXPECT_NO_THROW(requireClosed(m));
  EXPECT_NEAR(m.bounds.size().z, 4.0, 1e-6);

  // The same box without its last face.
  TopoDS_Shell open;
  BRep_Builder builder;
  builder.MakeShell(open);
  TopExp_Explorer it(box, TopAbs_FACE);
  for (int i = 0; i < 5; ++i, it.Next()) builder.Add(open, it.Current());
  const std::string openPath = dir.file("open.brep");
  ASSERT_TRUE(BRepTools::Write(open, openPath.c_str()));
  expectBadInput([&] { readModel(openPath); }, "5 faces");
}

TEST(Model, OpenMeshFailsRequireClosed) {
  test::TempDir dir;
  const std::string path =
      dir.write("open.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n");
  const Model m = readModel(path);  // reading an open mesh is fine...
  EXPECT_EQ(m.mesh.triangles.size(), 3u);
  expectBadInput([&] { requireClosed(m); }, "3 boundary edges");  // ...slicing it is not
  expectBadInput([&] { requireClosed(m); }, "open.off");
}

}  // namespace
}  // namespace sliceform
