// SPDX-License-Identifier: LGPL-2.1-or-later
#include "output/triangulate.hpp"

#include <GL/glu.h>

#include <cstdint>
#include <memory>
#include <string>

#include "support/error.hpp"

namespace sliceform {
namespace {

struct State {
  Triangles out;
  std::vector<int> pending;  // corners of the triangle being received
  GLenum error = 0;
};

int indexOf(void* vertex) {
  return static_cast<int>(reinterpret_cast<std::intptr_t>(vertex));
}

void GLAPIENTRY onVertex(void* vertex, void* state) {
  State& s = *static_cast<State*>(state);
  s.pending.push_back(indexOf(vertex));
  if (s.pending.size() == 3) {
    s.out.corners.push_back({s.pending[0], s.pending[1], s.pending[2]});
    s.pending.clear();
  }
}

// Where loops cross or touch, GLU asks for a new point; it lies on the plane already.
void GLAPIENTRY onCombine(GLdouble coords[3], void* /*around*/[4], GLfloat /*weights*/[4], void** made,
                          void* state) {
  State& s = *static_cast<State*>(state);
  s.out.points.push_back({coords[0], coords[1], coords[2]});
  *made = reinterpret_cast<void*>(static_cast<std::intptr_t>(s.out.points.size() - 1));
}

// With an edge-flag callback GLU sends separate triangles only (no fans, no strips).
void GLAPIENTRY onEdgeFlag(GLboolean, void*) {}

void GLAPIENTRY onError(GLenum error, void* state) {
  static_cast<State*>(state)->error = error;
}

using Tess = std::unique_ptr<GLUtesselator, decltype(&gluDeleteTess)>;

}  // namespace

Triangles triangulate(const std::vector<std::vector<Vec3>>& loops, const Vec3& normal) {
  State state;
  // GLU keeps pointers to the coordinates until the polygon ends: they must not move.
  std::vector<std::array<GLdouble, 3>> coords;
  size_t total = 0;
  for (const auto& loop : loops) total += loop.size();
  coords.reserve(total);
  state.out.points.reserve(total);
  Tess tess(gluNewTess(), &gluDeleteTess);
  if (!tess) throw Error(ErrorKind::Geometry, "cannot start GLU's tessellator");
  gluTessProperty(tess.get(), GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_ODD);
  gluTessNormal(tess.get(), normal.x, normal.y, normal.z);
  gluTessCallback(tess.get(), GLU_TESS_VERTEX_DATA, reinterpret_cast<_GLUfuncptr>(&onVertex));
  gluTessCallback(tess.get(), GLU_TESS_COMBINE_DATA, reinterpret_cast<_GLUfuncptr>(&onCombine));
  gluTessCallback(tess.get(), GLU_TESS_EDGE_FLAG_DATA, reinterpret_cast<_GLUfuncptr>(&onEdgeFlag));
  gluTessCallback(tess.get(), GLU_TESS_ERROR_DATA, reinterpret_cast<_GLUfuncptr>(&onError));
  gluTessBeginPolygon(tess.get(), &state);
  for (const auto& loop : loops) {
    gluTessBeginContour(tess.get());
    for (const Vec3& p : loop) {
      coords.push_back({p.x, p.y, p.z});
      state.out.points.push_back(p);
      gluTessVertex(tess.get(), coords.back().data(),
                    reinterpret_cast<void*>(static_cast<std::intptr_t>(state.out.points.size() - 1)));
    }
    gluTessEndContour(tess.get());
  }
  gluTessEndPolygon(tess.get());
  if (state.error != 0)
    throw Error(ErrorKind::Geometry, std::string("cannot triangulate a patch: ") +
                                         reinterpret_cast<const char*>(gluErrorString(state.error)));
  return std::move(state.out);
}

}  // namespace sliceform
