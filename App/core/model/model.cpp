// SPDX-License-Identifier: LGPL-2.1-or-later
#include "model/model.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <Poly_PolygonOnTriangulation.hxx>
#include <Poly_Triangulation.hxx>
#include <Precision.hxx>
#include <RWStl.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>

#include <boost/pending/disjoint_sets.hpp>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include "support/error.hpp"
#include "support/occt_guard.hpp"
#include "support/parallel.hpp"

namespace sliceform {
namespace {

// What the shape reaches for sure: its vertices and 17 points along each edge's curve. Each
// lies on the shape within the largest tolerance it claims, returned in `slack`.
Bnd_Box reached(const TopoDS_Shape& shape, double& slack) {
  Bnd_Box box;
  slack = 0;
  for (TopExp_Explorer ex(shape, TopAbs_VERTEX); ex.More(); ex.Next()) {
    const TopoDS_Vertex& v = TopoDS::Vertex(ex.Current());
    box.Add(BRep_Tool::Pnt(v));
    slack = std::max(slack, BRep_Tool::Tolerance(v));
  }
  for (TopExp_Explorer ex(shape, TopAbs_EDGE); ex.More(); ex.Next()) {
    const TopoDS_Edge& e = TopoDS::Edge(ex.Current());
    slack = std::max(slack, BRep_Tool::Tolerance(e));
    if (BRep_Tool::Degenerated(e)) continue;
    const BRepAdaptor_Curve c(e);
    for (int i = 0; i <= 16; ++i)
      box.Add(c.Value(c.FirstParameter() + i * (c.LastParameter() - c.FirstParameter()) / 16));
  }
  return box;
}

// BRepBndLib::AddOptimal on the geometry, not the triangulation, face by face on every core.
// It bounds each face on its own and takes the union (then the edges outside faces and the
// vertices outside edges), so the union of its boxes for each face is the box it gives for
// the shape, to the bit. Its global search on curved faces was most of reading a CAD part
// (occ/Top.brep: 2.0 of 2.9 s, tori and B-splines). A part whose plain box (BRepBndLib::Add:
// a B-spline's poles, a conic's whole arc) lies inside what the shape surely reaches, by
// more than the shape's largest tolerance and 10 µm, sets no side of the union and is not
// searched (occ/Bottom.brep: 41 of 323 faces searched, reading 0.94 -> 0.46 s).
Bnd_Box exactBounds(const TopoDS_Shape& shape) {
  std::vector<TopoDS_Shape> parts;
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) parts.push_back(ex.Current());
  for (TopExp_Explorer ex(shape, TopAbs_EDGE, TopAbs_FACE); ex.More(); ex.Next())
    parts.push_back(ex.Current());
  for (TopExp_Explorer ex(shape, TopAbs_VERTEX, TopAbs_EDGE); ex.More(); ex.Next())
    parts.push_back(ex.Current());
  double slack = 0;
  const Bnd_Box sure = reached(shape, slack);
  const double margin = slack + 0.01;
  double b[6];
  if (!sure.IsVoid()) sure.Get(b[0], b[1], b[2], b[3], b[4], b[5]);
  // Whether the part's plain box lies inside `sure` by more than `margin` on every side.
  const auto within = [&](const TopoDS_Shape& part) {
    if (sure.IsVoid()) return false;
    Bnd_Box plain;
    BRepBndLib::Add(part, plain, Standard_False);
    if (plain.IsVoid()) return false;
    double a[6];
    plain.Get(a[0], a[1], a[2], a[3], a[4], a[5]);
    for (int i = 0; i < 3; ++i)
      if (!(a[i] > b[i] + margin && a[i + 3] < b[i + 3] - margin)) return false;
    return true;
  };
  std::vector<Bnd_Box> boxes(parts.size());
  parallelFor(parts.size(), [&](size_t k) {
    occtGuard("measuring the shape", [&] {
      if (!within(parts[k])) BRepBndLib::AddOptimal(parts[k], boxes[k], Standard_False);
    });
  });
  Bnd_Box box;
  for (const Bnd_Box& b : boxes)
    if (!b.IsVoid()) {
      double x0, y0, z0, x1, y1, z1;
      b.Get(x0, y0, z0, x1, y1, z1);
      box.Update(x0, y0, z0, x1, y1, z1);
    }
  return box;
}

namespace fs = std::filesystem;

std::string lowerExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

Mesh fromPoly(const Handle(Poly_Triangulation) & poly) {
  Mesh mesh;
  mesh.vertices.reserve(poly->NbNodes());
  for (Standard_Integer i = 1; i <= poly->NbNodes(); ++i) {
    const gp_Pnt p = poly->Node(i);
    mesh.vertices.push_back({p.X(), p.Y(), p.Z()});
  }
  mesh.triangles.reserve(poly->NbTriangles());
  for (Standard_Integer i = 1; i <= poly->NbTriangles(); ++i) {
    Standard_Integer a, b, c;
    poly->Triangle(i).Get(a, b, c);
    // Out-of-range indices are caught by validateMesh: keep them out of range (not negative).
    auto id = [](Standard_Integer k) { return static_cast<uint32_t>(k < 1 ? UINT32_MAX : k - 1); };
    mesh.triangles.push_back({id(a), id(b), id(c)});
  }
  return mesh;
}

TopoDS_Shape readCad(const std::string& path, const std::string& ext) {
  if (ext == ".brep" || ext == ".brp") {
    TopoDS_Shape shape;
    BRep_Builder builder;
    if (!BRepTools::Read(shape, path.c_str(), builder) || shape.IsNull())
      throw Error(ErrorKind::BadInput, path + ": not a readable BREP file");
    return shape;
  }
  auto transfer = [&](XSControl_Reader& reader, const char* format) {
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
      throw Error(ErrorKind::BadInput, path + ": not a readable " + format + " file");
    reader.TransferRoots();
    TopoDS_Shape shape = reader.OneShape();
    if (shape.IsNull()) throw Error(ErrorKind::BadInput, path + ": the " + format + " file holds no shape");
    return shape;
  };
  if (ext == ".step" || ext == ".stp") {
    STEPControl_Reader reader;
    return transfer(reader, "STEP");
  }
  IGESControl_Reader reader;
  return transfer(reader, "IGES");
}

// A file that is removed when this goes out of scope.
struct TemporaryFile {
  std::string path;
  ~TemporaryFile() {
    if (!path.empty()) std::remove(path.c_str());
  }
};

// The path to give OCCT 7.6's STL reader (RWStl::ReadFile), kept from two faults that
// fuzzing found in it:
// - Binary STL (told apart as OCCT does: at least 134 bytes, one of the first 134 above
//   '~') is read as blocks of an 84-byte header, whose last 4 bytes count the facets, and
//   the 50-byte facets. OCCT sizes a map by that count before it reads a facet: 300 bytes
//   claiming 800 million facets made it allocate 13 GB. A count the file cannot hold is
//   refused here.
// - Its line reader (Standard_ReadLineBuffer) hands back the last line of a file that does
//   not end with a newline without a terminating NUL, and the ASCII reader then compares
//   and parses past the end of its buffer (heap-buffer-overflow). Such a file is read from
//   a temporary copy (`copy`) with a newline appended.
std::string stlForOcct(const std::string& path, TemporaryFile& copy) {
  std::ifstream in(path, std::ios::binary);
  char head[134];
  const std::streamsize n = in.read(head, sizeof head).gcount();
  if (n == sizeof head &&
      std::any_of(head, head + n, [](char c) { return static_cast<unsigned char>(c) > '~'; })) {
    std::error_code ec;
    const uintmax_t size = fs::file_size(path, ec);
    // The blocks as OCCT walks them, skipping white space between them.
    for (uintmax_t at = 0; !ec && at + 84 <= size;) {
      unsigned char header[84];
      in.clear();
      if (!in.seekg(static_cast<std::streamoff>(at)).read(reinterpret_cast<char*>(header), 84)) break;
      const auto facets = static_cast<int32_t>(header[80] | header[81] << 8 | header[82] << 16 |
                                               static_cast<uint32_t>(header[83]) << 24);
      const uintmax_t room = (size - at - 84) / 50;
      if (facets > 0 && static_cast<uintmax_t>(facets) > room)
        throw Error(ErrorKind::BadInput, path + ": the binary STL header at byte " + std::to_string(at) +
                                             " counts " + std::to_string(facets) +
                                             " triangles, the file has room for " + std::to_string(room) +
                                             " (cut short, or not an STL file)");
      at += 84 + 50 * static_cast<uintmax_t>(std::max(facets, 0));
      in.seekg(static_cast<std::streamoff>(at));
      for (int c = in.get(); c != EOF && std::isspace(c); c = in.get()) ++at;
    }
    return path;
  }
  in.clear();
  char last = '\n';
  in.seekg(-1, std::ios::end).get(last);
  if (last == '\n') return path;
  std::error_code ec;
  const fs::path folder = fs::temp_directory_path(ec);
  std::string name = ((ec ? fs::path("/tmp") : folder) / "sliceform-XXXXXX.stl").string();
  const int fd = ::mkstemps(name.data(), 4);  // created here, so no other file is overwritten
  if (fd < 0) throw Error(ErrorKind::Io, "cannot create a temporary copy of " + path + " in " + name);
  ::close(fd);
  copy.path = name;
  std::ofstream out(name, std::ios::binary);
  in.clear();
  in.seekg(0);
  out << in.rdbuf() << '\n';
  if (!out.flush()) throw Error(ErrorKind::Io, "cannot write a temporary copy of " + path + " to " + name);
  return name;
}

Mesh readMeshFile(const std::string& path, const std::string& ext) {
  if (ext == ".off") return readOff(path);
  Mesh mesh;
  if (ext == ".obj") {
    mesh = readObj(path);
  } else {
    TemporaryFile copy;
    const Handle(Poly_Triangulation) poly = RWStl::ReadFile(stlForOcct(path, copy).c_str());
    if (!poly.IsNull()) mesh = fromPoly(poly);
  }
  if (mesh.triangles.empty())
    throw Error(ErrorKind::BadInput, path + ": no triangles could be read from the file");
  return mesh;
}

// The solids of a shape; closed shells become solids, anything else is refused.
TopoDS_Shape solidsOf(const TopoDS_Shape& shape, const std::string& source) {
  TopoDS_Compound solids;
  BRep_Builder builder;
  builder.MakeCompound(solids);
  int count = 0;
  for (TopExp_Explorer it(shape, TopAbs_SOLID); it.More(); it.Next()) {
    // A solid without faces encloses nothing (and Booleans take it for an infinite solid).
    if (!TopExp_Explorer(it.Current(), TopAbs_FACE).More()) continue;
    builder.Add(solids, it.Current());
    ++count;
  }
  for (TopExp_Explorer it(shape, TopAbs_SHELL, TopAbs_SOLID); it.More(); it.Next()) {
    if (!BRep_Tool::IsClosed(it.Current())) continue;
    BRepBuilderAPI_MakeSolid maker(TopoDS::Shell(it.Current()));
    if (maker.IsDone()) {
      builder.Add(solids, maker.Solid());
      ++count;
    }
  }
  if (count == 0) {
    int faces = 0;
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) ++faces;
    throw Error(ErrorKind::BadInput, source + ": the shape holds no closed solid (" + std::to_string(faces) +
                                         " faces, none enclosing a volume); a sliceform needs a solid");
  }
  return solids;
}

// The triangulation OCCT attached to each face of `solid`, gathered into one welded mesh
// with the triangles turned to face outwards.
Mesh gatherTriangulation(const TopoDS_Shape& solid) {
  Mesh mesh;
  // Nodes on a shared BRep edge are joined through the edge's polygon on each face's
  // triangulation (node k of edge E is one point, whatever the face). Welding by exact
  // coordinates alone left cracks: each face's nodes are moved by that face's location, and
  // the same point moved by two different transformations can differ in the last bits
  // (valid closed solids such as occ/Bottom.brep or CrankArm.brep were refused as "not
  // closed").
  TopTools_IndexedMapOfShape edges;                   // same TShape and location: same edge
  std::map<std::pair<int, int>, uint32_t> edgeNodes;  // (edge, node k) -> first vertex seen
  std::vector<std::pair<uint32_t, uint32_t>> joins;   // vertices that are one point
  for (TopExp_Explorer it(solid, TopAbs_FACE); it.More(); it.Next()) {
    const TopoDS_Face& face = TopoDS::Face(it.Current());
    TopLoc_Location location;
    Handle(Poly_Triangulation) poly = BRep_Tool::Triangulation(face, location);
    if (poly.IsNull()) continue;
    const gp_Trsf trsf = location.Transformation();
    const auto base = static_cast<uint32_t>(mesh.vertices.size());
    for (Standard_Integer i = 1; i <= poly->NbNodes(); ++i) {
      const gp_Pnt p = poly->Node(i).Transformed(trsf);
      mesh.vertices.push_back({p.X(), p.Y(), p.Z()});
    }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (Standard_Integer i = 1; i <= poly->NbTriangles(); ++i) {
      Standard_Integer a, b, c;
      poly->Triangle(i).Get(a, b, c);
      if (reversed) std::swap(b, c);
      mesh.triangles.push_back({base + a - 1, base + b - 1, base + c - 1});
    }
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
      const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
      const Handle(Poly_PolygonOnTriangulation)& polygon =
          BRep_Tool::PolygonOnTriangulation(edge, poly, location);
      if (polygon.IsNull()) continue;
      const int id = edges.Add(edge);
      const double tolerance = BRep_Tool::Tolerance(edge);
      for (Standard_Integer k = 1; k <= polygon->NbNodes(); ++k) {
        const Standard_Integer node = polygon->Node(k);
        if (node < 1 || node > poly->NbNodes()) continue;
        const uint32_t v = base + node - 1;
        const auto [first, added] = edgeNodes.emplace(std::make_pair(id, k), v);
        // Join only nodes that coincide, should two faces ever order an edge's nodes apart.
        if (!added && norm(mesh.vertices[first->second] - mesh.vertices[v]) <= tolerance)
          joins.emplace_back(v, first->second);
      }
    }
  }
  boost::disjoint_sets_with_storage<> points(mesh.vertices.size());
  for (const auto& [a, b] : joins) points.union_set(a, b);
  for (auto& t : mesh.triangles)
    for (uint32_t& v : t) v = static_cast<uint32_t>(points.find_set(v));
  return weldExact(mesh);
}

// The triangulation of every solid, each welded on its own: solids of an assembly that
// touch share points, and welding them into one another turned their common edges into
// edges of four triangles, so closed solids (occ/Motor-c.brep) were refused as non-manifold.
Mesh triangulate(const TopoDS_Shape& shape, double deflection) {
  BRepMesh_IncrementalMesh mesher(shape, deflection, Standard_False, 0.35, Standard_True);
  Mesh mesh;
  for (TopExp_Explorer it(shape, TopAbs_SOLID); it.More(); it.Next()) {
    const Mesh part = gatherTriangulation(it.Current());
    const auto base = static_cast<uint32_t>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), part.vertices.begin(), part.vertices.end());
    for (const auto& t : part.triangles) mesh.triangles.push_back({base + t[0], base + t[1], base + t[2]});
  }
  return mesh;
}

}  // namespace

Model readModel(const std::string& path, bool fillEveryHole) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw Error(ErrorKind::BadInput, path + ": no such file");
  if (fs::file_size(path, ec) == 0) throw Error(ErrorKind::BadInput, path + ": the file is empty");
  const std::string ext = lowerExtension(path);
  static const char* cad[] = {".step", ".stp", ".iges", ".igs", ".brep", ".brp"};
  static const char* meshes[] = {".stl", ".obj", ".off"};
  if (std::find(std::begin(cad), std::end(cad), ext) != std::end(cad))
    return modelFromShape(occtGuard("reading the CAD file", [&] { return readCad(path, ext); }), path);
  if (std::find(std::begin(meshes), std::end(meshes), ext) != std::end(meshes))
    return modelFromMesh(occtGuard("reading the mesh file", [&] { return readMeshFile(path, ext); }), path,
                         fillEveryHole);
  throw Error(ErrorKind::BadInput,
              path + ": unknown format \"" + ext + "\" (expected STEP, IGES, BREP, STL, OBJ or OFF)");
}

Model modelFromShape(const TopoDS_Shape& shape, const std::string& source, double deflection) {
  if (shape.IsNull()) throw Error(ErrorKind::BadInput, source + ": the shape is empty");
  Model model;
  model.source = source;
  model.kind = SourceKind::Brep;
  model.shape = occtGuard("finding the solids", [&] { return solidsOf(shape, source); });
  // Make every edge's tolerance cover the distance between its 3D curve and its curves on
  // the faces. Imported files can understate it (step/linkrods.step: up to 4e-4 mm against
  // 1e-7), and OCCT's Booleans then drop parts of a section without any error, so the exact
  // slicer returned wrong areas. Like the triangulation below, this updates the shape's
  // edges in place.
  occtGuard("checking the shape's edges",
            [&] { BRepLib::SameParameter(model.shape, Precision::Confusion(), Standard_True); });
  const Bnd_Box box = occtGuard("measuring the shape", [&] { return exactBounds(model.shape); });
  if (box.IsVoid()) throw Error(ErrorKind::BadInput, source + ": the shape has no extent");
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  model.bounds.add({x0, y0, z0});
  model.bounds.add({x1, y1, z1});
  model.meshDeflection = deflection > 0 ? deflection : 1e-3 * model.bounds.diagonal();
  model.mesh =
      occtGuard("triangulating the shape", [&] { return triangulate(model.shape, model.meshDeflection); });
  validateMesh(model.mesh, source);
  return model;
}

Model modelFromMesh(const Mesh& mesh, const std::string& source, bool fillEveryHole) {
  validateMesh(mesh, source);
  Model model;
  model.source = source;
  model.kind = SourceKind::Mesh;
  model.mesh = weldExact(mesh);
  if (model.mesh.triangles.empty())
    throw Error(ErrorKind::BadInput, source + ": every triangle has zero area (repeated vertices)");
  model.bounds = model.mesh.bounds();
  // The sheets apart first: a hole's rim through a point they shared is then a loop of its own.
  model.edgesSplit = splitNonManifoldEdges(model.mesh);
  model.holesFilled =
      fillSmallHoles(model.mesh, fillEveryHole ? HUGE_VAL : kMaxFilledHoleSpan * model.bounds.diagonal());
  model.everyHoleFilled = fillEveryHole;
  return model;
}

Model scaledToSize(const Model& model, double longestSide) {
  const Vec3 size = model.bounds.size();
  const double longest = std::max({size.x, size.y, size.z});
  if (!(longestSide > 0) || !std::isfinite(longestSide))
    throw Error(ErrorKind::BadParameter, "the size must be a positive length in mm");
  if (!(longest > 0)) throw Error(ErrorKind::BadInput, model.source + ": the model has no extent");
  const double factor = longestSide / longest;
  Model out = model;
  for (Vec3& v : out.mesh.vertices) v = v * factor;
  out.bounds = Box3{};
  out.bounds.add(model.bounds.min * factor);
  out.bounds.add(model.bounds.max * factor);
  out.meshDeflection = model.meshDeflection * factor;
  if (!model.shape.IsNull()) {
    gp_Trsf scale;
    scale.SetScale(gp_Pnt(0, 0, 0), factor);
    out.shape = occtGuard("scaling the shape",
                          [&] { return BRepBuilderAPI_Transform(model.shape, scale, true).Shape(); });
  }
  return out;
}

Model scaledToHeight(const Model& model, Vec3 up, double height) {
  if (!(height > 0) || !std::isfinite(height))
    throw Error(ErrorKind::BadParameter, "the height must be a positive length in mm");
  const Interval w = model.mesh.extent(normalized(up));
  if (!(w.hi - w.lo > 0))
    throw Error(ErrorKind::BadInput, model.source + ": the model has no height to scale");
  const Vec3 box = model.bounds.size();
  return scaledToSize(model, std::max({box.x, box.y, box.z}) * height / (w.hi - w.lo));
}

void requireClosed(const Model& model) {
  const MeshTopology topo = analyseTopology(model.mesh);
  if (topo.closed()) return;
  std::string message = model.source + ": " + topo.describe();
  // A rim that touches itself or another hole's where three or more fans of triangles meet
  // gets no fan (fill_holes.cpp), whatever its size, and the message says so.
  if (topo.boundaryEdges > 0 && model.kind == SourceKind::Mesh && model.everyHoleFilled)
    message +=
        "; every hole that could be was filled (--fill-holes): the rims of these touch where three or "
        "more fans of triangles meet";
  else if (topo.boundaryEdges > 0 && topo.nonManifoldEdges == 0 && model.kind == SourceKind::Mesh)
    message +=
        "; holes up to " + std::to_string(static_cast<int>(kMaxFilledHoleSpan * 100)) +
        " % of the model's size across are filled: these are larger, or their rims touch where three or "
        "more fans of triangles meet (--fill-holes fills every hole, with a fan of triangles about its "
        "centre: flat where the rim is)";
  if (topo.nonManifoldEdges > 0 && model.kind == SourceKind::Mesh)
    message +=
        "; edges where closed parts meet are split apart, these could not be (an odd number of triangles "
        "on the edge, or more running one way along it than the other: flipped or doubled triangles)";
  throw Error(ErrorKind::BadInput, message);
}

std::vector<size_t> separateSolids(const Mesh& mesh) {
  // Connected pieces of the (welded) mesh, then pieces grouped while their boxes touch:
  // a void inside a solid, or solids of an assembly that touch, stay one object.
  boost::disjoint_sets_with_storage<> vertices(mesh.vertices.size());
  for (const auto& t : mesh.triangles) {
    vertices.union_set(t[0], t[1]);
    vertices.union_set(t[0], t[2]);
  }
  std::map<size_t, size_t> pieceOf;
  std::vector<Box3> boxes;
  std::vector<size_t> triangles;
  for (const auto& t : mesh.triangles) {
    const auto [it, added] = pieceOf.emplace(vertices.find_set(t[0]), boxes.size());
    if (added) boxes.emplace_back(), triangles.push_back(0);
    for (uint32_t v : t) boxes[it->second].add(mesh.vertices[v]);
    ++triangles[it->second];
  }
  const double gap = 1e-6 * mesh.bounds().diagonal();
  auto touch = [gap](const Box3& a, const Box3& b) {
    return a.min.x <= b.max.x + gap && b.min.x <= a.max.x + gap && a.min.y <= b.max.y + gap &&
           b.min.y <= a.max.y + gap && a.min.z <= b.max.z + gap && b.min.z <= a.max.z + gap;
  };
  // Sweep along x so a soup of many small pieces is not compared pair by pair.
  std::vector<size_t> order(boxes.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return boxes[a].min.x < boxes[b].min.x; });
  boost::disjoint_sets_with_storage<> groups(boxes.size());
  for (size_t i = 0; i < order.size(); ++i)
    for (size_t j = i + 1; j < order.size() && boxes[order[j]].min.x <= boxes[order[i]].max.x + gap; ++j)
      if (touch(boxes[order[i]], boxes[order[j]])) groups.union_set(order[i], order[j]);
  std::map<size_t, size_t> count;
  for (size_t i = 0; i < boxes.size(); ++i) count[groups.find_set(i)] += triangles[i];
  std::vector<size_t> out;
  for (const auto& [group, n] : count) out.push_back(n);
  std::sort(out.rbegin(), out.rend());
  return out;
}

void requireOneSolid(const Model& model) {
  const std::vector<size_t> solids = separateSolids(model.mesh);
  if (solids.size() <= 1) return;
  std::string sizes;
  for (size_t i = 0; i < solids.size() && i < 5; ++i) sizes += (i ? ", " : "") + std::to_string(solids[i]);
  throw Error(ErrorKind::BadInput,
              model.source + ": the model is " + std::to_string(solids.size()) + " separate solids (" +
                  sizes + (solids.size() > 5 ? ", ..." : "") +
                  " triangles); one sliceform holds one solid together: design each on its own");
}

}  // namespace sliceform
