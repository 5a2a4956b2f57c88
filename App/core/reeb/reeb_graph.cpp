// SPDX-License-Identifier: LGPL-2.1-or-later
#include "reeb/reeb_graph.hpp"

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <map>
#include <utility>

#include "support/parallel.hpp"

namespace sliceform {
namespace {

bool boxesOverlap(const Box2& a, const Box2& b) {
  return !a.empty && !b.empty && a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y &&
         b.min.y <= a.max.y;
}

// Pieces of consecutive slices are joined when they overlap by a real share of the smaller
// one. Any overlap at all is not enough: separate parts that touch (a ball resting on its
// stand, occ/Ball.brep) overlap each other's next section by a sliver at every slice, and
// the graph turned into a ladder of one-slice edges (170 of them instead of 4).
constexpr double kMinOverlapShare = 0.2;

bool overlap(const Region2d& a, const Region2d& b) {
  if (!boxesOverlap(a.bounds(), b.bounds())) return false;
  const double common = a.intersect(b).area();
  return common > 0 && common >= kMinOverlapShare * std::min(a.area(), b.area());
}

// Renumbers vertices 0..n-1 after edges were removed or joined.
void compactVertices(ReebGraph& g) {
  std::map<int, int> ids;
  for (ReebEdge& e : g.edges) {
    for (int* v : {&e.tail, &e.head}) *v = ids.emplace(*v, static_cast<int>(ids.size())).first->second;
  }
  g.vertexCount = static_cast<int>(ids.size());
}

// Connected pieces of the graph with edge `skip` left out.
int componentCount(const ReebGraph& g, int skip) {
  std::vector<int> parent(g.vertexCount), rank(g.vertexCount);
  boost::disjoint_sets<int*, int*> sets(rank.data(), parent.data());
  for (int v = 0; v < g.vertexCount; ++v) sets.make_set(v);
  for (int e = 0; e < static_cast<int>(g.edges.size()); ++e)
    if (e != skip) sets.union_set(g.edges[e].tail, g.edges[e].head);
  std::vector<int> used(g.vertexCount, 0);
  for (int e = 0; e < static_cast<int>(g.edges.size()); ++e) {
    if (e == skip) continue;
    used[g.edges[e].tail] = used[g.edges[e].head] = 1;
  }
  int count = 0;
  for (int v = 0; v < g.vertexCount; ++v) count += used[v] && sets.find_set(v) == v ? 1 : 0;
  return count;
}

// Removing edge e keeps the graph's pieces together: a dangling branch, or one edge of a
// loop (the thin side of a small ring), but never a bridge between two parts.
bool removable(const ReebGraph& g, int e) {
  const ReebEdge& s = g.edges[e];
  const bool dangling = g.incoming(s.tail).size() + g.outgoing(s.tail).size() == 1 ||
                        g.incoming(s.head).size() + g.outgoing(s.head).size() == 1;
  return dangling || componentCount(g, e) == componentCount(g, -1);
}

// One merge of §4.1.2 if any applies; false when the graph is simplified.
bool mergeOnce(ReebGraph& g, double tauM) {
  for (int v = 0; v < g.vertexCount; ++v) {
    const std::vector<int> in = g.incoming(v), out = g.outgoing(v);
    if (in.size() == 1 && out.size() == 1 && in[0] != out[0]) {
      ReebEdge& e = g.edges[in[0]];
      ReebEdge& next = g.edges[out[0]];
      e.patches.insert(e.patches.end(), next.patches.begin(), next.patches.end());
      e.head = next.head;
      g.edges.erase(g.edges.begin() + out[0]);
      compactVertices(g);
      return true;
    }
    // Left merge (one outgoing, several incoming) or right merge (the mirror).
    const bool left = out.size() == 1 && in.size() > 1;
    const bool right = in.size() == 1 && out.size() > 1;
    if (!left && !right) continue;
    const int keep = left ? out[0] : in[0];
    for (int small : left ? in : out) {
      const ReebEdge& s = g.edges[small];
      if (!(s.weight() < tauM * g.edges[keep].weight()) || !removable(g, small)) continue;
      ReebEdge& k = g.edges[keep];
      Region2d& cap = left ? k.patches.front() : k.patches.back();
      std::vector<Region2d> all = s.patches;
      all.push_back(cap);
      cap = Region2d::uniteAll(all);
      g.edges.erase(g.edges.begin() + small);
      compactVertices(g);
      return true;
    }
  }
  return false;
}

}  // namespace

double ReebEdge::weight() const {
  double w = 0;
  for (const Region2d& p : patches) w += p.area();
  return w;
}

std::vector<int> ReebGraph::incoming(int vertex) const {
  std::vector<int> out;
  for (size_t i = 0; i < edges.size(); ++i)
    if (edges[i].head == vertex) out.push_back(static_cast<int>(i));
  return out;
}

std::vector<int> ReebGraph::outgoing(int vertex) const {
  std::vector<int> out;
  for (size_t i = 0; i < edges.size(); ++i)
    if (edges[i].tail == vertex) out.push_back(static_cast<int>(i));
  return out;
}

int ReebGraph::componentCount() const {
  return sliceform::componentCount(*this, -1);
}

int ReebGraph::cycleRank() const {
  return static_cast<int>(edges.size()) - vertexCount + componentCount();
}

ReebGraph buildReebGraph(const SliceSet& set) {
  // Nodes: the pieces of every slice; links: overlaps between consecutive slices.
  const int slices = static_cast<int>(set.slices.size());
  // Each slice's pieces, and each pair of consecutive slices' overlaps, on every core: pair
  // i writes only next[i] and prev[i + 1], in the order one core would (ChineseDragon: the
  // stage had run on one core, 110 ms, while the other waited).
  std::vector<std::vector<Region2d>> pieces(slices);
  parallelFor(static_cast<size_t>(slices), [&](size_t i) { pieces[i] = set.slices[i].region.components(); });
  std::vector<std::vector<std::vector<int>>> next(slices), prev(slices);
  for (int i = 0; i < slices; ++i) {
    next[i].resize(pieces[i].size());
    prev[i].resize(pieces[i].size());
  }
  parallelFor(static_cast<size_t>(std::max(slices - 1, 0)), [&](size_t i) {
    for (size_t a = 0; a < pieces[i].size(); ++a) {
      for (size_t b = 0; b < pieces[i + 1].size(); ++b) {
        if (!overlap(pieces[i][a], pieces[i + 1][b])) continue;
        next[i][a].push_back(static_cast<int>(b));
        prev[i + 1][b].push_back(static_cast<int>(a));
      }
    }
  });
  // Edges: maximal runs where a piece has one successor and that successor one predecessor.
  ReebGraph g;
  std::map<std::pair<int, int>, int> edgeOfFirst, edgeOfLast;
  auto continues = [&](int i, int a) {
    return prev[i][a].size() == 1 && next[i - 1][prev[i][a][0]].size() == 1;
  };
  for (int i = 0; i < slices; ++i) {
    for (int a = 0; a < static_cast<int>(pieces[i].size()); ++a) {
      if (i > 0 && continues(i, a)) continue;
      ReebEdge e;
      e.firstSlice = i;
      int s = i, p = a;
      e.patches.push_back(pieces[s][p]);
      while (s + 1 < slices && next[s][p].size() == 1 && prev[s + 1][next[s][p][0]].size() == 1) {
        p = next[s][p][0];
        ++s;
        e.patches.push_back(pieces[s][p]);
      }
      edgeOfFirst[{i, a}] = static_cast<int>(g.edges.size());
      edgeOfLast[{s, p}] = static_cast<int>(g.edges.size());
      g.edges.push_back(std::move(e));
    }
  }
  // Vertices: an edge's head is joined with the tails of the edges its last piece leads to.
  const int ends = 2 * static_cast<int>(g.edges.size());  // tail of edge k = 2k, head = 2k + 1
  std::vector<int> rank(ends), parent(ends);
  boost::disjoint_sets<int*, int*> sets(rank.data(), parent.data());
  for (int k = 0; k < ends; ++k) sets.make_set(k);
  for (const auto& [last, edge] : edgeOfLast) {
    for (int b : next[last.first][last.second])
      sets.union_set(2 * edge + 1, 2 * edgeOfFirst.at({last.first + 1, b}));
  }
  for (size_t k = 0; k < g.edges.size(); ++k) {
    g.edges[k].tail = sets.find_set(2 * static_cast<int>(k));
    g.edges[k].head = sets.find_set(2 * static_cast<int>(k) + 1);
  }
  compactVertices(g);
  return g;
}

void simplifyReebGraph(ReebGraph& graph, double tauM) {
  while (mergeOnce(graph, tauM)) {
  }
}

}  // namespace sliceform
