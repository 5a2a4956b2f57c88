// SPDX-License-Identifier: LGPL-2.1-or-later
// Reeb graph of a slice set (§4.1.2): the connected pieces of every slice, joined where
// pieces of consecutive slices overlap. Runs of pieces that neither split nor merge are
// the graph's edges; the places where pieces split, merge, start or end are its vertices.
#pragma once

#include <vector>

#include "geometry/region2d.hpp"
#include "slicing/slice_set.hpp"

namespace sliceform {

struct ReebEdge {
  int firstSlice = 0;             // slice index of patches.front()
  std::vector<Region2d> patches;  // one per consecutive slice from firstSlice on
  int tail = -1, head = -1;       // vertex before the first patch, vertex after the last

  int lastSlice() const { return firstSlice + static_cast<int>(patches.size()) - 1; }
  double weight() const;  // sum of the patch areas (the paper's w(e)), mm²
};

struct ReebGraph {
  std::vector<ReebEdge> edges;
  int vertexCount = 0;

  std::vector<int> incoming(int vertex) const;  // edges whose head is `vertex`
  std::vector<int> outgoing(int vertex) const;  // edges whose tail is `vertex`
  int componentCount() const;                   // connected pieces
  int cycleRank() const;                        // independent cycles: edges - vertices + pieces
};

ReebGraph buildReebGraph(const SliceSet& set);

// Merges small branches into large ones until nothing changes (§4.1.2, Fig. 7):
// - at a vertex with one outgoing edge e and several incoming edges, an incoming e' with
//   w(e')/w(e) < tauM is left-merged into e (e's first patch becomes its union with all of
//   e''s patches) and removed; mirrored for one incoming and several outgoing edges;
// - an edge that ends where exactly one other edge starts is joined with it.
// Decision: a small edge is absorbed only if the graph stays in as many pieces (a dangling
// branch, or one side of a small loop); a bridge between two parts is kept.
void simplifyReebGraph(ReebGraph& graph, double tauM);

}  // namespace sliceform
