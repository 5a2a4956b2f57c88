// SPDX-License-Identifier: LGPL-2.1-or-later
// Triangle meshes: what STL/OBJ/OFF files hold, and what the search stages slice (a BRep
// source is triangulated once for them).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "geometry/vec.hpp"

namespace sliceform {

struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;

  Box3 bounds() const;
  // Smallest and largest dot(v, direction) over the vertices.
  Interval extent(const Vec3& direction) const;
};

// What makes a mesh unusable as a solid, counted edge by edge.
struct MeshTopology {
  size_t boundaryEdges = 0;                              // used by one triangle: the mesh has holes
  size_t nonManifoldEdges = 0;                           // used by three or more triangles
  size_t holes = 0;                                      // closed loops of boundary edges
  size_t degenerateTriangles = 0;                        // a repeated vertex index
  std::vector<std::array<Vec3, 2>> sampleBoundaryEdges;  // a few, to show the user
  std::vector<std::array<Vec3, 2>> sampleNonManifoldEdges;

  bool closed() const { return boundaryEdges == 0 && nonManifoldEdges == 0; }
  std::string describe() const;
};

MeshTopology analyseTopology(const Mesh& mesh);

// One key per undirected mesh edge, whatever the order of its two vertices.
inline uint64_t edgeKey(uint32_t a, uint32_t b) {
  if (a > b) std::swap(a, b);
  return (uint64_t{a} << 32) | b;
}

// Merges vertices with bit-identical coordinates (STL soups, per-face BRep triangulations
// whose shared edges carry the same nodes) and drops triangles that collapse.
Mesh weldExact(const Mesh& mesh);

// Throws BadInput if a coordinate is NaN or infinite or an index is out of range.
void validateMesh(const Mesh& mesh, const std::string& source);

}  // namespace sliceform
