// SPDX-License-Identifier: LGPL-2.1-or-later
#include "slicing/torus_section.hpp"

#include <GeomAPI_Interpolate.hxx>
#include <Precision.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_HArray1OfPnt.hxx>

#include <algorithm>
#include <cmath>
#include <functional>

namespace sliceform {
namespace {

constexpr double kTwoPi = 2 * M_PI;
// mm between a loop and the exact curve: 1 µm, the finest deflection exact edges are ever
// polygonised to (exactDeflection). At 1 nm, loops of up to 2,048 points made the exact
// patches' fuses and slot cuts slower than the sections gained (occt-misc Axis_of_bearing
// 6.9 -> 10.0 s, screw.step 0.41 -> 1.04 s); at 1 µm they are 4.5 and 0.48 s.
constexpr double kTolerance = 1e-3;
constexpr int kFewest = 16, kMost = 2048;  // points a loop is interpolated through

// The periodic B-spline through `at` at `count` equal steps of its parameter, and its
// largest distance from `at` halfway between them.
std::pair<Handle(Geom_BSplineCurve), double> interpolate(const std::function<gp_Pnt(double)>& at, int count) {
  Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, count);
  Handle(TColStd_HArray1OfReal) parameters = new TColStd_HArray1OfReal(1, count + 1);
  for (int i = 0; i <= count; ++i) {
    const double t = kTwoPi * i / count;
    if (i < count) points->SetValue(i + 1, at(t));
    parameters->SetValue(i + 1, t);  // one more: the junction's parameter at the end
  }
  GeomAPI_Interpolate interpolation(points, parameters, Standard_True, Precision::Confusion());
  interpolation.Perform();
  if (!interpolation.IsDone()) return {nullptr, HUGE_VAL};
  const Handle(Geom_BSplineCurve) curve = interpolation.Curve();
  double error = 0;
  for (int i = 0; i < count; ++i) {
    const double t = kTwoPi * (i + 0.5) / count;
    error = std::max(error, curve->Value(t).Distance(at(t)));
  }
  return {curve, error};
}

}  // namespace

std::optional<TorusSection> torusSection(const gp_Torus& torus, const gp_Pln& plane) {
  const gp_XYZ z = torus.Axis().Direction().XYZ(), n = plane.Axis().Direction().XYZ();
  const double big = torus.MajorRadius(), small = torus.MinorRadius();
  if (std::abs(z.Dot(n)) > Precision::Angular() || !(small > 0)) return std::nullopt;
  // In the plane: o the axis's foot, e across the axis, z along it. The tube's circle at t
  // lies at rho = R + r cos t from the axis (negative past it, on a spindle torus, R < r)
  // and at height r sin t; it meets the plane at s = ±sqrt(rho² - delta²) across.
  const double delta = n.Dot(plane.Location().XYZ() - torus.Location().XYZ()), away = std::abs(delta);
  const double near = 1e-9 * (big + small);
  TorusSection out;
  if (away > big + small + near) return out;
  // Tangent outside; the plane through the axis, or where loops touch (the hole's rim).
  if (away >= big + small - near || away <= near || std::abs(away - std::abs(big - small)) <= near)
    return std::nullopt;
  const gp_XYZ o = torus.Location().XYZ() + delta * n, e = n.Crossed(z);
  const auto point = [=](double s, double t) { return gp_Pnt(o + e * s + z * (small * std::sin(t))); };
  const auto across = [=](double t) {
    const double rho = big + small * std::cos(t);
    return std::sqrt(std::max(0.0, rho * rho - delta * delta));
  };
  // A loop over the tube's part |t - mid| <= half, where |rho| >= |delta|: with
  // t = mid + half sin(phi) its two halves meet at s = 0 smoothly in phi (s runs through
  // zero linearly there).
  const auto loop = [=](double mid, double half) {
    return [=](double phi) {
      const double t = mid + half * std::sin(phi);
      return point(std::cos(phi) >= 0 ? across(t) : -across(t), t);
    };
  };
  std::vector<std::function<gp_Pnt(double)>> loops;
  if (away < big - small) {
    // Two loops, one each side of the axis, each round the whole tube.
    for (const double side : {1.0, -1.0})
      loops.push_back([=](double t) { return point(side * across(t), t); });
  } else {
    loops.push_back(loop(0, std::acos((away - big) / small)));  // rho >= |delta|
    // A spindle torus's inner part, past the axis, rho <= -|delta|.
    if (away < small - big) loops.push_back(loop(M_PI, std::acos((away + big) / small)));
  }
  for (const auto& at : loops) {
    std::pair<Handle(Geom_BSplineCurve), double> fit{nullptr, HUGE_VAL};
    for (int count = kFewest; count <= kMost && fit.second > kTolerance; count *= 2)
      fit = interpolate(at, count);
    if (fit.second > kTolerance) return std::nullopt;
    out.loops.push_back(fit.first);
    out.tolerance = std::max(out.tolerance, fit.second);
  }
  return out;
}

}  // namespace sliceform
