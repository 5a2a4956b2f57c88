// SPDX-License-Identifier: LGPL-2.1-or-later
#include "arrangement/arrange.hpp"

#include <cmath>
#include <sstream>

#include "slicing/mesh_slicer.hpp"
#include "support/error.hpp"
#include "support/stopwatch.hpp"

namespace sliceform {
namespace {

void checkParams(const ArrangementParams& p) {
  const double nu = norm(p.u), nv = norm(p.v);
  if (!(nu > 0) || !(nv > 0) || !std::isfinite(nu) || !std::isfinite(nv))
    throw Error(ErrorKind::BadParameter, "the slicing directions must be finite non-zero vectors");
  if (std::fabs(dot(p.u, p.v)) > 1e-6 * nu * nv)
    throw Error(ErrorKind::BadParameter, "the slicing directions U and V must be orthogonal");
  if (p.interval <= 0 && (p.slices < 2 || p.slices > 4096))
    throw Error(ErrorKind::BadParameter, "the number of slices must be between 2 and 4096");
  if (!(p.tauA >= 0) || !(p.tauM >= 0 && p.tauM < 1))
    throw Error(ErrorKind::BadParameter, "tauA must be >= 0 and tauM in [0, 1)");
  if (!(p.hinges.minHingeLength >= 0) || !(p.hinges.minSlotEdgeDistance >= 0))
    throw Error(ErrorKind::BadParameter, "hinge length and slot edge distance must be >= 0");
  minPatchSpacing(p.stabilize, p.hinges);  // throws when below what the slots need
}

SliceSet sliceFamily(const Model& model, const SliceFrame& frame, const ArrangementParams& p) {
  const Interval range = model.mesh.extent(frame.normal);
  int count = p.slices;
  if (p.interval > 0) {
    const double n = std::floor((range.hi - range.lo) / p.interval);
    if (n > 4096) throw Error(ErrorKind::BadParameter, "the slice interval gives more than 4096 slices");
    count = std::max(2, static_cast<int>(n));
  }
  return sliceMesh(model.mesh, frame, uniformPositions(range.lo, range.hi, count));
}

std::string mm(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

Arrangement arrange(const Model& model, const ArrangementParams& params, const Arrangement* earlier) {
  checkParams(params);
  requireClosed(model);
  requireOneSolid(model);
  Arrangement a;
  a.params = params;
  Stopwatch clock(a.timings);
  const ArrangementParams* was = earlier ? &earlier->params : nullptr;
  const bool sameSlices = was && was->u == params.u && was->v == params.v && was->slices == params.slices &&
                          was->interval == params.interval;
  if (sameSlices) {
    a.stagesTaken = 1;
    a.u = earlier->u;
    a.v = earlier->v;
  } else {
    const Vec3 w = cross(params.u, params.v);
    a.u = sliceFamily(model, makeSliceFrame(params.u, w), params);
    a.v = sliceFamily(model, makeSliceFrame(params.v, w), params);
  }
  clock.lap("slice");

  const bool sameReeb = sameSlices && was->tauM == params.tauM;
  if (sameReeb) {
    a.stagesTaken = 2;
    a.reebU = earlier->reebU;
    a.reebV = earlier->reebV;
  } else {
    a.reebU = buildReebGraph(a.u);
    a.reebV = buildReebGraph(a.v);
    simplifyReebGraph(a.reebU, params.tauM);
    simplifyReebGraph(a.reebV, params.tauM);
  }
  clock.lap("reeb");

  // Neighbouring cylinders must be able to hold patches the spacing rule apart.
  const double spacing = a.minSpacing = minPatchSpacing(params.stabilize, params.hinges);
  const int uApart = slicesApart(spacing, a.u.interval), vApart = slicesApart(spacing, a.v.interval);
  if (sameReeb && was->tauA == params.tauA && slicesApart(earlier->minSpacing, a.u.interval) == uApart &&
      slicesApart(earlier->minSpacing, a.v.interval) == vApart) {
    a.stagesTaken = 3;
    a.uCylinders = earlier->uCylinders;
    a.vCylinders = earlier->vCylinders;
  } else {
    a.uCylinders = approximateCylinders(a.reebU, Family::U, a.u.interval, params.tauA, uApart);
    a.vCylinders = approximateCylinders(a.reebV, Family::V, a.v.interval, params.tauA, vApart);
  }
  clock.lap("gca");

  a.table = std::make_shared<const HingeTable>(a.u, a.v, a.uCylinders, a.vCylinders, params.hinges);
  a.scaffold = stabilize(a.u, a.v, a.uCylinders, a.vCylinders, *a.table, params.stabilize);
  clock.lap("frames");
  if (a.scaffold.patches.empty()) {
    throw Error(ErrorKind::Unbuildable,
                model.source +
                    ": no two U-patches and two V-patches can hold each other with hinges of at least " +
                    mm(params.hinges.minHingeLength) + " mm and " + mm(params.hinges.minSlotEdgeDistance) +
                    " mm of paper beside each slot; the model is too thin or too small for these settings "
                    "(try a larger --size, or a smaller --min-hinge-length or --min-slot-edge-distance)");
  }

  a.certificate = certifyScaffold(a.scaffold);
  clock.lap("certificate");

  // The slices and cylinders taken from the earlier arrangement: their measures too.
  a.qualityBase =
      a.stagesTaken == 3 && earlier->qualityBase
          ? earlier->qualityBase
          : std::make_shared<const QualityBase>(qualityBase(a.u, a.v, a.uCylinders, a.vCylinders));
  a.quality = measureQuality(*a.qualityBase, a.u, a.v, a.uCylinders, a.vCylinders, a.scaffold);
  clock.lap("quality");
  return a;
}

Certificate certifyScaffold(const Scaffold& s) {
  std::vector<BarPatch> bars;
  for (const ScaffoldPatch& p : s.patches) bars.push_back({p.family, p.position});
  std::vector<PinHinge> pins;
  for (const ScaffoldHinge& h : s.hinges)
    if (h.holds) pins.push_back({h.u, h.v});
  return certify(bars, pins);
}

void remeasure(Arrangement& a) {
  a.certificate = certifyScaffold(a.scaffold);
  if (!a.qualityBase)
    a.qualityBase = std::make_shared<const QualityBase>(qualityBase(a.u, a.v, a.uCylinders, a.vCylinders));
  a.quality = measureQuality(*a.qualityBase, a.u, a.v, a.uCylinders, a.vCylinders, a.scaffold);
}

PatchPlane patchPlane(const Arrangement& a, int patch) {
  const ScaffoldPatch& p = a.scaffold.patches[patch];
  const SliceFrame& f = a.slices(p.family).frame;
  return {f.normal * p.position, f.normal, f.xAxis, f.yAxis};
}

std::pair<Vec3, Vec3> hingeEnds(const Arrangement& a, const ScaffoldHinge& h) {
  // The point on both planes at height w: U, V, W are orthonormal.
  const Vec3 base = a.u.frame.normal * a.scaffold.patches[h.u].position +
                    a.v.frame.normal * a.scaffold.patches[h.v].position;
  const Vec3& up = a.u.frame.yAxis;
  return {base + up * h.w.lo, base + up * h.w.hi};
}

}  // namespace sliceform
