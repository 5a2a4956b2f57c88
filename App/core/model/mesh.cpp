// SPDX-License-Identifier: LGPL-2.1-or-later
#include "model/mesh.hpp"

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <unordered_map>

#include "support/error.hpp"

namespace sliceform {
namespace {

struct Vec3Hash {
  size_t operator()(const Vec3& v) const {
    uint64_t h = 1469598103934665603ull;
    for (double c : {v.x, v.y, v.z}) {
      uint64_t bits;
      c = c == 0.0 ? 0.0 : c;  // +0 and -0 are the same point
      std::memcpy(&bits, &c, sizeof bits);
      h = (h ^ bits) * 1099511628211ull;
    }
    return static_cast<size_t>(h);
  }
};

// "(x, y, z)-(x, y, z)", to name an edge to the user.
std::string edgeText(const std::array<Vec3, 2>& e) {
  std::ostringstream out;
  out << "(" << e[0].x << ", " << e[0].y << ", " << e[0].z << ")-(" << e[1].x << ", " << e[1].y << ", "
      << e[1].z << ")";
  return out.str();
}

}  // namespace

Box3 Mesh::bounds() const {
  Box3 box;
  for (const Vec3& v : vertices) box.add(v);
  return box;
}

Interval Mesh::extent(const Vec3& direction) const {
  Interval range{HUGE_VAL, -HUGE_VAL};
  for (const Vec3& v : vertices) {
    const double d = dot(v, direction);
    range.lo = std::min(range.lo, d);
    range.hi = std::max(range.hi, d);
  }
  return range;
}

std::string MeshTopology::describe() const {
  std::ostringstream out;
  if (boundaryEdges > 0) {
    out << "the mesh is not closed: " << boundaryEdges << " boundary edge" << (boundaryEdges == 1 ? "" : "s")
        << " in " << holes << " hole" << (holes == 1 ? "" : "s");
    if (!sampleBoundaryEdges.empty())
      out << " (for example the edge " << edgeText(sampleBoundaryEdges[0]) << ")";
  }
  if (nonManifoldEdges > 0) {
    if (boundaryEdges > 0) out << "; ";
    out << nonManifoldEdges << " non-manifold edge" << (nonManifoldEdges == 1 ? "" : "s")
        << " (shared by three or more triangles";
    if (!sampleNonManifoldEdges.empty())
      out << ", for example the edge " << edgeText(sampleNonManifoldEdges[0]);
    out << ")";
  }
  return out.str();
}

MeshTopology analyseTopology(const Mesh& mesh) {
  MeshTopology topo;
  std::vector<uint64_t> edges;
  edges.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
      ++topo.degenerateTriangles;
      continue;
    }
    for (int i = 0; i < 3; ++i) edges.push_back(edgeKey(t[i], t[(i + 1) % 3]));
  }
  std::sort(edges.begin(), edges.end());
  // Union-find over vertex ids: each set of joined boundary vertices is one hole.
  boost::disjoint_sets_with_storage<> loops(mesh.vertices.size());
  std::vector<uint32_t> boundaryVertices;
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    const size_t uses = j - i;
    if (uses == 1) {
      const auto a = static_cast<uint32_t>(edges[i] >> 32), b = static_cast<uint32_t>(edges[i]);
      ++topo.boundaryEdges;
      loops.union_set(a, b);
      boundaryVertices.push_back(a);
      if (topo.sampleBoundaryEdges.size() < 3)
        topo.sampleBoundaryEdges.push_back({mesh.vertices[a], mesh.vertices[b]});
    } else if (uses > 2) {
      ++topo.nonManifoldEdges;
      const auto a = static_cast<uint32_t>(edges[i] >> 32), b = static_cast<uint32_t>(edges[i]);
      if (topo.sampleNonManifoldEdges.size() < 3)
        topo.sampleNonManifoldEdges.push_back({mesh.vertices[a], mesh.vertices[b]});
    }
    i = j;
  }
  // Each set of joined boundary vertices is one hole.
  std::vector<uint32_t> roots;
  roots.reserve(boundaryVertices.size());
  for (uint32_t v : boundaryVertices) roots.push_back(loops.find_set(v));
  std::sort(roots.begin(), roots.end());
  topo.holes = static_cast<size_t>(std::unique(roots.begin(), roots.end()) - roots.begin());
  return topo;
}

Mesh weldExact(const Mesh& mesh) {
  Mesh out;
  std::unordered_map<Vec3, uint32_t, Vec3Hash> index;
  index.reserve(mesh.vertices.size());
  std::vector<uint32_t> remap(mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& v = mesh.vertices[i];
    auto [it, added] = index.emplace(v, static_cast<uint32_t>(out.vertices.size()));
    if (added) out.vertices.push_back(v);
    remap[i] = it->second;
  }
  out.triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const std::array<uint32_t, 3> w{remap[t[0]], remap[t[1]], remap[t[2]]};
    if (w[0] != w[1] && w[1] != w[2] && w[2] != w[0]) out.triangles.push_back(w);
  }
  return out;
}

void validateMesh(const Mesh& mesh, const std::string& source) {
  if (mesh.triangles.empty()) throw Error(ErrorKind::BadInput, source + ": the mesh has no triangles");
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& v = mesh.vertices[i];
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      throw Error(ErrorKind::BadInput,
                  source + ": vertex " + std::to_string(i + 1) + " has a NaN or infinite coordinate");
  }
  const size_t n = mesh.vertices.size();
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    for (uint32_t v : mesh.triangles[i]) {
      if (v >= n)
        throw Error(ErrorKind::BadInput, source + ": triangle " + std::to_string(i + 1) + " uses vertex " +
                                             std::to_string(v + 1) + " of " + std::to_string(n));
    }
  }
}

}  // namespace sliceform
