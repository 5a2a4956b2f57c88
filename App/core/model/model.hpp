// SPDX-License-Identifier: LGPL-2.1-or-later
// Model: the source solid as the pipeline sees it. A CAD source keeps its exact OCCT shape
// (for the exact patches) plus a triangulation (for the search stages); a mesh source is
// the triangulation alone. Lengths are millimetres: STEP and IGES are converted by OCCT,
// BREP and mesh files carry no unit and are taken as millimetres.
#pragma once

#include <TopoDS_Shape.hxx>

#include <string>

#include "model/mesh.hpp"

namespace sliceform {

enum class SourceKind { Brep, Mesh };

struct Model {
  std::string source;  // file name or a caller's label, for messages
  SourceKind kind = SourceKind::Mesh;
  TopoDS_Shape shape;            // the solids, for BRep sources; null for meshes
  Mesh mesh;                     // closed triangle mesh, welded
  Box3 bounds;                   // of the shape (or mesh), mm
  double meshDeflection = 0;     // how far the triangulation may stray from the shape, mm
  size_t holesFilled = 0;        // small holes of a mesh source closed on reading
  bool everyHoleFilled = false;  // the user asked for every hole filled, not only small ones
  size_t edgesSplit = 0;         // edges where closed sheets of a mesh source touch, split on reading
};

// Holes of a mesh are filled when they are at most this share of the model's bounding-box
// diagonal across; larger ones are refused by requireClosed, unless the user asks for every
// hole filled (`--fill-holes`: fillEveryHole), as for the Newell teapot's open rim.
constexpr double kMaxFilledHoleSpan = 0.2;

// Reads STEP, IGES, BREP, STL, OBJ or OFF (chosen by the file extension); a mesh's holes are
// filled, the small ones or (fillEveryHole) all.
Model readModel(const std::string& path, bool fillEveryHole = false);

// Solids of `shape` (closed shells are made solids), triangulated for the search stages.
// `deflection` <= 0 picks 1/1000 of the bounding box diagonal.
Model modelFromShape(const TopoDS_Shape& shape, const std::string& source, double deflection = 0);
Model modelFromMesh(const Mesh& mesh, const std::string& source, bool fillEveryHole = false);

// The model scaled about the origin so that its longest side is `longestSide` mm.
Model scaledToSize(const Model& model, double longestSide);
// The model scaled about the origin so that its extent along `up` is `height` mm.
Model scaledToHeight(const Model& model, Vec3 up, double height);

// Throws BadInput naming the boundary and non-manifold edges if the mesh is not closed.
void requireClosed(const Model& model);

// Triangle counts of the model's separate solids, largest first: connected pieces whose
// bounding boxes do not touch (a void, or touching parts of an assembly, are not separate).
std::vector<size_t> separateSolids(const Mesh& mesh);
// Throws BadInput naming the pieces if there is more than one separate solid.
void requireOneSolid(const Model& model);

// Readers of the mesh formats OCCT has no reader for.
Mesh readOff(const std::string& path);
// Closes every hole at most maxSpan across (its bounding-box diagonal) with a fan of triangles about its
// centroid; returns how many. A hole through a vertex shared with another hole (a pinch) is left.
size_t fillSmallHoles(Mesh& mesh, double maxSpan);
// Splits the edges of three or more triangles where closed sheets touch along the edge:
// the triangles are paired across the material about the edge, and the edge's ends get a
// copy for every fan the pairing separates. Edges that cannot be paired so (an odd count,
// flipped or doubled triangles) are left. Returns how many edges were split.
size_t splitNonManifoldEdges(Mesh& mesh);
// Vertices and faces of an OBJ file (polygons fanned); throws BadInput naming the line of
// the first statement it cannot read, such as a face with a vertex index out of range.
Mesh readObj(const std::string& path);

}  // namespace sliceform
