// SPDX-License-Identifier: LGPL-2.1-or-later
// Sliceform arrangement (§4): from a model to a certified scaffold. Runs the stages in
// order (slice sets, Reeb graphs, cylinders, hinge table, stabilization, certificate,
// quality) and times each one.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cylinders/gca.hpp"
#include "frames/hinge_table.hpp"
#include "frames/scaffold.hpp"
#include "frames/stabilize.hpp"
#include "model/model.hpp"
#include "quality/quality.hpp"
#include "reeb/reeb_graph.hpp"
#include "support/stopwatch.hpp"
#include "verify/certificate.hpp"

namespace sliceform {

struct ArrangementParams {
  Vec3 u{1, 0, 0}, v{0, 1, 0};  // slicing directions, orthogonal; W = U x V is up
  int slices = 128;             // per direction, unless interval > 0
  double interval = 0;          // mm between slices; > 0 overrides `slices`
  double tauA = 0.1;            // cylinder error budget, relative to the part's volume
  double tauM = 0.03;           // Reeb branch merging threshold (weight ratio)
  HingeRules hinges;
  StabilizeOptions stabilize;
};
inline bool operator==(const ArrangementParams& a, const ArrangementParams& b) {
  return a.u == b.u && a.v == b.v && a.slices == b.slices && a.interval == b.interval && a.tauA == b.tauA &&
         a.tauM == b.tauM && a.hinges == b.hinges && a.stabilize == b.stabilize;
}

struct Arrangement {
  ArrangementParams params;  // what it was made from
  SliceSet u, v;
  ReebGraph reebU, reebV;
  std::vector<Cylinder> uCylinders, vCylinders;
  std::shared_ptr<const HingeTable> table;  // where patches of any two cylinders hinge
  Scaffold scaffold;
  double minSpacing = 0;  // mm, the spacing rule in force (minPatchSpacing)
  Certificate certificate;
  std::shared_ptr<const QualityBase> qualityBase;  // of the slices and cylinders
  Quality quality;
  std::vector<StageTime> timings;
  int stagesTaken = 0;  // of slice, reeb and gca, how many were taken from an earlier arrangement

  // Family f's slice set and cylinders.
  const SliceSet& slices(Family f) const { return f == Family::U ? u : v; }
  const std::vector<Cylinder>& cylinders(Family f) const { return f == Family::U ? uCylinders : vCylinders; }
};

// Throws BadParameter for directions that are not orthogonal or out-of-range values.
// `earlier`: an arrangement of the same model (a FreeCAD edit designs again): the slice sets,
// Reeb graphs and cylinders are taken from it where their inputs are the same (no later stage
// changes them), as a Thickness edit leaves them unless the slices a patch spacing needs
// change.
Arrangement arrange(const Model& model, const ArrangementParams& params,
                    const Arrangement* earlier = nullptr);

// The certificate of a scaffold on its holding hinges.
Certificate certifyScaffold(const Scaffold& scaffold);
// The certificate and quality again, after patches of the scaffold moved.
void remeasure(Arrangement& arrangement);

// Where a patch lies in 3D: origin (on the plane), normal and in-plane axes, mm.
struct PatchPlane {
  Vec3 origin, normal, xAxis, yAxis;
};
PatchPlane patchPlane(const Arrangement& a, int patch);
// The ends of a hinge in 3D.
std::pair<Vec3, Vec3> hingeEnds(const Arrangement& a, const ScaffoldHinge& h);

}  // namespace sliceform
