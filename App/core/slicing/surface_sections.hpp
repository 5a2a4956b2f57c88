// SPDX-License-Identifier: LGPL-2.1-or-later
// The curves where a plane cuts a face's surface, solved analytically: planes, cylinders,
// cones and spheres, and tori across their axis (IntAna_QuadQuadGeo), tori along it
// (slicing/torus_section.hpp); and points projected onto them. What the face-by-face route
// (slicing/face_by_face.hpp) cuts each face's section from.
#pragma once

#include <BRepAdaptor_Surface.hxx>
#include <Bnd_Box.hxx>
#include <Geom_Curve.hxx>
#include <gp_Dir.hxx>
#include <gp_Pln.hxx>
#include <gp_Pnt.hxx>

#include <optional>
#include <utility>
#include <vector>

namespace sliceform {

// A curve of a face's section (a conic, or a torus's loop), the parameters it spans, and
// how far it may be from the exact intersection (0 for a conic).
struct SectionCurve {
  Handle(Geom_Curve) curve;
  double first = 0, last = 0;
  bool periodic = false;
  double tolerance = 0;
};

// The curves where the plane cuts the surface `s` of a face whose box is `box` (an
// unbounded curve spans the box: past it the curve is outside the face), appended to
// `out`; false where unsure: a surface of another kind (a B-spline, a surface of
// revolution, a torus cut aslant), a plane tangent to it.
bool planeSurfaceCurves(const BRepAdaptor_Surface& s, const gp_Pln& plane, const Bnd_Box& box,
                        std::vector<SectionCurve>& out);

// The foot of `p` on `curve` by Newton's method on the squared distance, from `t`, each
// step taken only where it comes nearer. ElCLib's parameter of a point off a conic is not
// its nearest point's: on an ellipse the offset across the major axis counts as many times
// over as the point lies further along the ellipse than the minor radius, up to the radii's
// ratio (a plane nearly along a cylinder's axis on occ/Top.brep: an ellipse 8972 x 28.6 mm,
// and a crossing 4 nm off the cylinder read as 1.2 µm off its section, which refused the
// plane).
double footOnCurve(const Geom_Curve& curve, const gp_Pnt& p, double t);

// The parameter of `p` on `c` and its distance from it.
std::pair<double, double> projectOnSection(const SectionCurve& c, const gp_Pnt& p);

// A crossing `p` of an edge that lies on none of the face's section curves to the
// tolerances (`budget[k]` for curve k) may still lie on the surface to them: where the
// plane cuts the surface at a grazing angle phi, a point a distance e off the surface in
// space lies up to e / sin(phi) off the section in the plane (occ/Bottom.brep: a crossing
// 17 nm off a cylinder, 0.59 µm off its section, sin(phi) 0.03; occ/Top.brep: 0.7 nm and
// 82 nm, 0.008). Its in-plane distance from the nearest curve, times sin(phi) at its foot,
// is then within that curve's budget: the curve, and its parameter there, or nullopt.
// `n` is the plane's normal.
std::optional<std::pair<size_t, double>> grazedFoot(const BRepAdaptor_Surface& s,
                                                    const std::vector<SectionCurve>& curves,
                                                    const std::vector<double>& budget, const gp_Pnt& p,
                                                    const gp_Dir& n);

}  // namespace sliceform
