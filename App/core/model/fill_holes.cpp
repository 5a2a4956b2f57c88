// SPDX-License-Identifier: LGPL-2.1-or-later
// Small holes of scanned meshes (a bunny's base, a teapot's spout tip) are closed with a
// fan of triangles about the hole's centroid; rims that touch at a vertex are split there
// first. Big holes are left for requireClosed to refuse unless the user asks for every
// hole (--fill-holes): a fan over a third of the model would invent a large flat face.
// Orientation of the new triangles does not matter: the slicer fills sections by the
// even-odd rule.
#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <vector>

#include "model/model.hpp"

namespace sliceform {
namespace {

bool degenerate(const std::array<uint32_t, 3>& t) {
  return t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
}

// Closes a loop of vertices with a fan about its centroid, if it is at most maxSpan across.
bool fan(Mesh& mesh, const std::vector<uint32_t>& loop, double maxSpan) {
  // Across: the diagonal of the hole's bounding box (linear in its size; a pairwise
  // maximum would be quadratic on a scan with a hole of 100,000 edges).
  Box3 box;
  for (uint32_t v : loop) box.add(mesh.vertices[v]);
  if (loop.size() < 3 || box.diagonal() > maxSpan) return false;
  Vec3 centre{0, 0, 0};
  for (uint32_t v : loop) centre = centre + mesh.vertices[v] * (1.0 / loop.size());
  const auto c = static_cast<uint32_t>(mesh.vertices.size());
  mesh.vertices.push_back(centre);
  for (size_t i = 0; i < loop.size(); ++i)
    mesh.triangles.push_back({loop[i], loop[(i + 1) % loop.size()], c});
  return true;
}

// Holes whose rims touch at a vertex (a pinch: a rim through it twice, or two holes
// through it) are split there into simple loops and filled. Each boundary edge runs as its
// one triangle has it. At a vertex with one edge in and one out the rim goes on. At a
// vertex where the triangles make two fans, each fan has one boundary edge in and one out,
// and the rim turns from one fan's edge in to the other fan's edge out: that is the gap
// between the fans, one corner of one hole. Vertices of more fans are left (their order
// around the vertex is not topology's to say), and so are the loops through them.
size_t fillPinchedHoles(Mesh& mesh, double maxSpan) {
  std::map<uint64_t, int> uses;
  for (const auto& t : mesh.triangles)
    if (!degenerate(t))
      for (int i = 0; i < 3; ++i) ++uses[edgeKey(t[i], t[(i + 1) % 3])];
  // Boundary edges, directed as their triangle runs; the triangles at each of their ends.
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  std::vector<size_t> owner;
  std::map<uint32_t, std::vector<size_t>> out, in;  // boundary edges from / to a vertex
  std::map<uint32_t, std::vector<size_t>> around;   // triangles at a pinched vertex
  for (size_t k = 0; k < mesh.triangles.size(); ++k) {
    const auto& t = mesh.triangles[k];
    if (degenerate(t)) continue;
    for (int i = 0; i < 3; ++i) {
      const uint32_t a = t[i], b = t[(i + 1) % 3];
      if (uses[edgeKey(a, b)] != 1) continue;
      out[a].push_back(edges.size());
      in[b].push_back(edges.size());
      edges.push_back({a, b});
      owner.push_back(k);
    }
  }
  for (const auto& [v, from] : out)
    if (from.size() == 2) around[v];
  for (size_t k = 0; k < mesh.triangles.size(); ++k) {
    const auto& t = mesh.triangles[k];
    if (degenerate(t)) continue;  // it would join every fan
    for (uint32_t v : t)
      if (auto it = around.find(v); it != around.end()) it->second.push_back(k);
  }
  std::vector<long> next(edges.size(), -1);  // the boundary edge after each, along its rim
  for (const auto& [v, from] : out) {
    const auto to = in.find(v);
    if (to == in.end() || to->second.size() != from.size()) continue;  // flipped triangles: left
    if (from.size() == 1) {
      next[to->second[0]] = static_cast<long>(from[0]);
      continue;
    }
    if (from.size() != 2) continue;
    // The fans: the triangles at v joined across their edges from v that two of them share.
    const std::vector<size_t>& ts = around[v];
    std::vector<size_t> fanOf(ts.size());
    std::iota(fanOf.begin(), fanOf.end(), 0);
    const auto find = [&](size_t i) {
      while (fanOf[i] != i) i = fanOf[i] = fanOf[fanOf[i]];
      return i;
    };
    for (size_t i = 0; i < ts.size(); ++i)
      for (size_t j = i + 1; j < ts.size(); ++j) {
        int shared = 0;
        for (uint32_t a : mesh.triangles[ts[i]])
          for (uint32_t b : mesh.triangles[ts[j]]) shared += a == b;
        if (shared == 2) fanOf[find(i)] = find(j);  // an edge from v, since both hold v
      }
    const auto fanAt = [&](size_t edge) {
      return find(static_cast<size_t>(std::find(ts.begin(), ts.end(), owner[edge]) - ts.begin()));
    };
    const size_t in0 = to->second[0], in1 = to->second[1], out0 = from[0], out1 = from[1];
    const size_t fans[] = {fanAt(in0), fanAt(in1), fanAt(out0), fanAt(out1)};
    if (fans[0] == fans[1] || fans[2] == fans[3]) continue;  // not two fans: left
    // In from one fan, out into the other.
    const bool straight = fans[0] != fans[2];
    next[in0] = static_cast<long>(straight ? out0 : out1);
    next[in1] = static_cast<long>(straight ? out1 : out0);
  }
  size_t filled = 0;
  std::vector<bool> used(edges.size(), false);
  for (size_t start = 0; start < edges.size(); ++start) {
    if (used[start]) continue;
    std::vector<uint32_t> loop;
    size_t e = start;
    bool closed = false;
    while (!used[e]) {
      used[e] = true;
      loop.push_back(edges[e].first);
      if (next[e] < 0) break;
      e = static_cast<size_t>(next[e]);
      closed = e == start;
    }
    std::vector<uint32_t> distinct = loop;
    std::sort(distinct.begin(), distinct.end());
    const bool simple = std::adjacent_find(distinct.begin(), distinct.end()) == distinct.end();
    if (closed && simple && fan(mesh, loop, maxSpan)) ++filled;
  }
  return filled;
}

}  // namespace

size_t fillSmallHoles(Mesh& mesh, double maxSpan) {
  std::map<uint64_t, int> uses;
  for (const auto& t : mesh.triangles)
    if (!degenerate(t))
      for (int i = 0; i < 3; ++i) ++uses[edgeKey(t[i], t[(i + 1) % 3])];
  std::map<uint32_t, std::vector<uint32_t>> next;  // boundary neighbours of each vertex
  for (const auto& [key, count] : uses) {
    if (count != 1) continue;
    const auto a = static_cast<uint32_t>(key >> 32), b = static_cast<uint32_t>(key);
    next[a].push_back(b);
    next[b].push_back(a);
  }
  // Simple loops first: a rim through a vertex it shares with another (a pinch) is left to
  // fillPinchedHoles.
  std::map<uint32_t, bool> done;
  size_t filled = 0;
  bool pinched = false;  // a boundary vertex with more than two boundary neighbours
  for (const auto& [start, neighbours] : next) {
    pinched = pinched || neighbours.size() > 2;
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
    if (simple && fan(mesh, loop, maxSpan)) ++filled;
  }
  // Then the rims that touch, split where they do: only where the simple rims are done, so
  // a mesh whose holes are all simple is filled as it always was (and not read again).
  return filled + (pinched ? fillPinchedHoles(mesh, maxSpan) : 0);
}

}  // namespace sliceform
