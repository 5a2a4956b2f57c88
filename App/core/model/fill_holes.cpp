// SPDX-License-Identifier: LGPL-2.1-or-later
// Small holes of scanned meshes (a bunny's base, a teapot's spout tip) are closed with a
// fan of triangles about the hole's centroid. Big holes are left for requireClosed to
// refuse: a fan over a third of the model would invent a large flat face. Orientation of
// the new triangles does not matter: the slicer fills sections by the even-odd rule.
#include <algorithm>
#include <map>
#include <vector>

#include "model/model.hpp"

namespace sliceform {

size_t fillSmallHoles(Mesh& mesh, double maxSpan) {
  std::map<uint64_t, int> uses;
  for (const auto& t : mesh.triangles)
    if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0])
      for (int i = 0; i < 3; ++i) ++uses[edgeKey(t[i], t[(i + 1) % 3])];
  std::map<uint32_t, std::vector<uint32_t>> next;  // boundary neighbours of each vertex
  for (const auto& [key, count] : uses) {
    if (count != 1) continue;
    const auto a = static_cast<uint32_t>(key >> 32), b = static_cast<uint32_t>(key);
    next[a].push_back(b);
    next[b].push_back(a);
  }
  // Only simple loops: a hole through a vertex on two holes (a pinch) is left alone.
  std::map<uint32_t, bool> done;
  size_t filled = 0;
  for (const auto& [start, neighbours] : next) {
    if (done[start] || neighbours.size() != 2) continue;
    std::vector<uint32_t> loop{start};
    uint32_t previous = start, current = neighbours[0];
    done[start] = true;
    bool simple = true;
    while (current != start) {
      const auto& n = next[current];
      if (n.size() != 2) {
        simple = false;
        break;
      }
      loop.push_back(current);
      done[current] = true;
      const uint32_t following = n[0] == previous ? n[1] : n[0];
      previous = current;
      current = following;
    }
    if (!simple) continue;
    // Across: the diagonal of the hole's bounding box (linear in its size; a pairwise
    // maximum would be quadratic on a scan with a hole of 100,000 edges).
    Box3 box;
    for (uint32_t v : loop) box.add(mesh.vertices[v]);
    if (loop.size() < 3 || box.diagonal() > maxSpan) continue;
    Vec3 centre{0, 0, 0};
    for (uint32_t v : loop) centre = centre + mesh.vertices[v] * (1.0 / loop.size());
    const auto c = static_cast<uint32_t>(mesh.vertices.size());
    mesh.vertices.push_back(centre);
    for (size_t i = 0; i < loop.size(); ++i)
      mesh.triangles.push_back({loop[i], loop[(i + 1) % loop.size()], c});
    ++filled;
  }
  return filled;
}

}  // namespace sliceform
