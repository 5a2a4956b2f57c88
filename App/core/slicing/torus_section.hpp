// SPDX-License-Identifier: LGPL-2.1-or-later
// The section of a torus by a plane along its axis: one closed quartic loop, or two (a
// spiric section), which no conic describes and IntAna_QuadQuadGeo does not solve. Its
// points come in closed form, so each loop is interpolated by a periodic cubic B-spline
// through them, with points added until the exact curve between them stays within 1 µm.
// Walking it (GeomInt_IntSS) cost as much as the whole section did.
#pragma once

#include <Geom_BSplineCurve.hxx>
#include <gp_Pln.hxx>
#include <gp_Torus.hxx>

#include <optional>
#include <vector>

namespace sliceform {

struct TorusSection {
  std::vector<Handle(Geom_BSplineCurve)> loops;  // each over [0, 2π), none where the plane misses
  double tolerance = 0;  // mm, the loops' largest distance from the exact curve, halfway between points
};

// nullopt where the plane is not along the torus's axis, or would need a guess: tangent to
// the torus, through its axis, where two loops touch (the hole's rim). Spindle tori (R < r)
// have an inner loop too.
std::optional<TorusSection> torusSection(const gp_Torus& torus, const gp_Pln& plane);

}  // namespace sliceform
