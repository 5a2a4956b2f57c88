// SPDX-License-Identifier: LGPL-2.1-or-later
// Edges shared by four, six... triangles, where closed sheets meet along an edge: two
// parts of a model touching at an edge, or two copies of a point that welding merged
// (cgal/diplodocus.off keeps two copies of two points apart, weldExact joins them). The
// slicer chains sections by edge, and at such an edge it paired the chain ends
// arbitrarily.
//
// Each triangle on the edge is paired with one running the other way along it, so every
// chain through the edge keeps its direction; the sections, filled by winding number, are
// then the same whichever such pairing is taken. The pairing chosen separates the sheets:
// - by the fans about an end of the edge: walking about the end from a triangle on the
//   edge, across edges of two triangles, until the edge is reached again (a point whose
//   copies were merged: each copy's fan leads from one of its triangles to the other);
// - else by angle about the edge: going round it, the triangles alternate in direction,
//   and each pairs with its neighbour across the material (parts touching, even face to
//   face, where a fan leads from the edge to another shared edge).
// The ends of each paired edge then get one copy of the point per fan the pairing
// separates. Edges that cannot be paired (an odd count, flipped or doubled triangles) are
// left for requireClosed to refuse.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include <boost/pending/disjoint_sets.hpp>

#include "model/model.hpp"

namespace sliceform {
namespace {

// A triangle's use of an edge: from t[corner] to t[corner + 1].
struct Use {
  uint64_t key;
  uint32_t triangle;
  uint32_t corner;
};

constexpr uint32_t kNone = UINT32_MAX;        // a boundary edge, or a shared one not paired yet
constexpr uint32_t kJoined = UINT32_MAX - 1;  // a shared edge left as it is

bool degenerate(const std::array<uint32_t, 3>& t) {
  return t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
}

class Splitter {
 public:
  explicit Splitter(Mesh& mesh) : mesh_(mesh) {
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto& v = mesh.triangles[t];
      if (degenerate(v)) continue;
      for (uint32_t c = 0; c < 3; ++c) uses_.push_back({edgeKey(v[c], v[(c + 1) % 3]), t, c});
    }
    std::sort(uses_.begin(), uses_.end(), [](const Use& p, const Use& q) {
      return p.key != q.key             ? p.key < q.key
             : p.triangle != q.triangle ? p.triangle < q.triangle
                                        : p.corner < q.corner;
    });
    partner_.assign(uses_.size(), kNone);
    useOf_.assign(3 * mesh.triangles.size(), kNone);
    for (uint32_t i = 0; i < uses_.size(); ++i) useOf_[3 * uses_[i].triangle + uses_[i].corner] = i;
  }

  size_t run() {
    std::vector<std::pair<uint32_t, uint32_t>> shared;  // edges of more than 2 uses, [first, last)
    for (uint32_t i = 0; i < uses_.size();) {
      uint32_t j = i;
      while (j < uses_.size() && uses_[j].key == uses_[i].key) ++j;
      if (j - i == 2) pair(i, i + 1);
      if (j - i > 2) shared.emplace_back(i, j);
      i = j;
    }
    if (shared.empty()) return 0;
    // Fans first (what the mesh's own connections say), angles where they say nothing, and
    // fans again through the edges paired by angle.
    std::vector<std::pair<uint32_t, uint32_t>> paired;
    for (int pass = 0; pass < 3; ++pass) {
      for (const auto& [first, last] : shared) {
        if (partner_[first] != kNone) continue;
        const uint32_t a = end(first, 0), b = end(first, 1);
        const bool done =
            pass == 1 ? pairAround(first, last) : pairByFan(first, last, a) || pairByFan(first, last, b);
        if (done) paired.emplace_back(first, last);
      }
    }
    for (const auto& [first, last] : shared)
      if (partner_[first] == kNone) std::fill(partner_.begin() + first, partner_.begin() + last, kJoined);
    if (paired.empty()) return 0;

    std::map<uint32_t, std::vector<uint32_t>> about;  // the triangles about each end
    for (const auto& [first, last] : paired) about[end(first, 0)], about[end(first, 1)];
    for (uint32_t t = 0; t < mesh_.triangles.size(); ++t) {
      if (degenerate(mesh_.triangles[t])) continue;  // keeps its corners
      for (uint32_t v : mesh_.triangles[t]) {
        const auto it = about.find(v);
        if (it != about.end()) it->second.push_back(t);
      }
    }
    for (const auto& [v, triangles] : about) splitPoint(v, triangles);
    // An edge is split when its pairs now run between different points; where the fans
    // about both ends stay joined, it is left shared and requireClosed names it.
    size_t split = 0;
    for (const auto& [first, last] : paired) {
      std::set<uint64_t> keys;
      for (uint32_t i = first; i < last; ++i) {
        const auto& t = mesh_.triangles[uses_[i].triangle];
        keys.insert(edgeKey(t[uses_[i].corner], t[(uses_[i].corner + 1) % 3]));
      }
      split += keys.size() == (last - first) / 2 ? 1 : 0;
    }
    return split;
  }

 private:
  // End 0 (the lower id) or 1 of the edge of use i, before any point is split.
  uint32_t end(uint32_t i, int which) const {
    return static_cast<uint32_t>(which == 0 ? uses_[i].key >> 32 : uses_[i].key & 0xffffffffu);
  }
  // The use runs from end 0 to end 1.
  bool forward(uint32_t i) const { return mesh_.triangles[uses_[i].triangle][uses_[i].corner] == end(i, 0); }

  void pair(uint32_t u, uint32_t w) {
    partner_[u] = w;
    partner_[w] = u;
  }

  // Pairs each use with the one its triangle's fan about v leads to, if that pairs them all,
  // each with a use running the other way.
  bool pairByFan(uint32_t first, uint32_t last, uint32_t v) {
    std::vector<uint32_t> found(last - first, kNone);
    for (uint32_t x = first; x < last; ++x) {
      uint32_t u = x;
      for (size_t step = 0; step <= uses_.size(); ++step) {
        // The other edge through v of u's triangle, then across it.
        const Use& use = uses_[u];
        const auto& t = mesh_.triangles[use.triangle];
        const uint32_t w =
            useOf_[3 * use.triangle + (t[use.corner] == v ? (use.corner + 2) % 3 : (use.corner + 1) % 3)];
        if (uses_[w].key == uses_[x].key) {
          found[x - first] = w;
          break;
        }
        if (partner_[w] >= kJoined) return false;  // a boundary or another shared edge
        u = partner_[w];
      }
    }
    for (uint32_t x = first; x < last; ++x) {
      const uint32_t y = found[x - first];
      if (y == kNone || y == x || found[y - first] != x || forward(x) == forward(y)) return false;
    }
    for (uint32_t x = first; x < last; ++x) partner_[x] = found[x - first];
    return true;
  }

  // Pairs the uses by angle about the edge, if they alternate in direction going round it.
  bool pairAround(uint32_t first, uint32_t last);
  // Gives v one copy per fan of the triangles about it.
  void splitPoint(uint32_t v, const std::vector<uint32_t>& triangles);

  Mesh& mesh_;
  std::vector<Use> uses_;          // by edge
  std::vector<uint32_t> partner_;  // the use across the edge from each use
  std::vector<uint32_t> useOf_;    // 3 * triangle + corner -> index in uses_
};

bool Splitter::pairAround(uint32_t first, uint32_t last) {
  if ((last - first) % 2) return false;
  const Vec3 pa = mesh_.vertices[end(first, 0)], axis = normalized(mesh_.vertices[end(first, 1)] - pa);
  struct Around {
    double angle;
    bool forward;  // running from end 0 to end 1, its normal turns towards larger angles
    uint32_t use;
  };
  std::vector<Around> around;
  Vec3 e1, e2;
  for (uint32_t i = first; i < last; ++i) {
    const auto& t = mesh_.triangles[uses_[i].triangle];
    const Vec3 d = mesh_.vertices[t[(uses_[i].corner + 2) % 3]] - pa;
    const Vec3 w = d - axis * dot(d, axis);  // towards the third corner, across the axis
    if (!(norm(w) > 0)) return false;        // a sliver on the axis has no side
    if (i == first) e1 = normalized(w), e2 = cross(axis, e1);
    double angle = std::atan2(dot(w, e2), dot(w, e1));
    if (angle < 0) angle += 2 * M_PI;
    around.push_back({angle, forward(i), i});
  }
  // Triangles at the same angle (faces of two parts lying on each other) touch: those whose
  // material lies below come first, so no wedge of material has zero width.
  constexpr double kSame = 1e-9;  // radians
  for (Around& r : around)
    if (r.angle > 2 * M_PI - kSame) r.angle -= 2 * M_PI;
  std::sort(around.begin(), around.end(), [](const Around& p, const Around& q) { return p.angle < q.angle; });
  const size_t n = around.size();
  for (size_t k = 0; k < n;) {
    size_t same = k + 1;
    while (same < n && around[same].angle - around[same - 1].angle <= kSame) ++same;
    std::stable_partition(around.begin() + k, around.begin() + same,
                          [](const Around& r) { return r.forward; });
    k = same;
  }
  for (size_t k = 0; k < n; ++k)
    if (around[k].forward == around[(k + 1) % n].forward) return false;  // flipped or doubled
  // A forward triangle's material lies towards smaller angles: its partner is the one before.
  for (size_t k = 0; k < n; ++k)
    if (around[k].forward) pair(around[k].use, around[(k + n - 1) % n].use);
  return true;
}

void Splitter::splitPoint(uint32_t v, const std::vector<uint32_t>& triangles) {
  // Triangles about v are one fan where they meet across an edge through v.
  std::map<uint32_t, size_t> local;
  for (size_t k = 0; k < triangles.size(); ++k) local[triangles[k]] = k;
  boost::disjoint_sets_with_storage<> fans(triangles.size());
  for (size_t k = 0; k < triangles.size(); ++k) {
    const auto& t = mesh_.triangles[triangles[k]];
    const auto c = static_cast<uint32_t>(std::find(t.begin(), t.end(), v) - t.begin());
    for (uint32_t corner : {c, (c + 2) % 3}) {  // the edges v -> next and previous -> v
      const uint32_t u = useOf_[3 * triangles[k] + corner];
      if (partner_[u] == kJoined) {  // all of its triangles stay together
        for (uint32_t i = u; i > 0 && uses_[i - 1].key == uses_[u].key; --i)
          fans.union_set(k, local.at(uses_[i - 1].triangle));
        for (uint32_t i = u + 1; i < uses_.size() && uses_[i].key == uses_[u].key; ++i)
          fans.union_set(k, local.at(uses_[i].triangle));
      } else if (partner_[u] != kNone) {
        fans.union_set(k, local.at(uses_[partner_[u]].triangle));
      }
    }
  }
  // The fan of the first triangle keeps v; every other fan gets a copy of the point.
  std::map<size_t, uint32_t> pointOf;
  for (size_t k = 0; k < triangles.size(); ++k) {
    auto [it, added] = pointOf.emplace(fans.find_set(k), v);
    if (added && pointOf.size() > 1) {
      it->second = static_cast<uint32_t>(mesh_.vertices.size());
      mesh_.vertices.push_back(mesh_.vertices[v]);
    }
    for (uint32_t& corner : mesh_.triangles[triangles[k]])
      if (corner == v) corner = it->second;
  }
}

}  // namespace

size_t splitNonManifoldEdges(Mesh& mesh) {
  return Splitter(mesh).run();
}

}  // namespace sliceform
