// SPDX-License-Identifier: LGPL-2.1-or-later
// How well a scaffold depicts the model. Decisions, since the paper gives no measure:
// - silhouette along U (V): the union of the U (V) slices, i.e. the model seen along U,
//   against the union of the U-patches' shapes; intersection over union of the two areas;
// - silhouette along W: in the (U, V) plane, the model's footprint (for every U slice, the
//   V-extent of its material, one slice interval wide) against the lattice's footprint (the
//   same strips for the slices that carry a patch, in both families); it tells how evenly
//   the patches visit the model seen from above;
// - volume IoU: the slices swept by one interval against the cylinders swept the same way,
//   slice by slice (intersection over union of the material and the cylinders spanning
//   it), the smaller of the two families. Cylinders need not contain their slices (Reeb
//   simplification moves an absorbed branch into its neighbour's end patch).
#pragma once

#include <vector>

#include "cylinders/gca.hpp"
#include "frames/scaffold.hpp"

namespace sliceform {

struct Quality {
  double silhouetteIouU = 0, silhouetteIouV = 0, silhouetteIouW = 0;
  double volumeIou = 0;
};

// What the measures read of the slices and cylinders alone, whatever the scaffold: the
// union of each family's slices, the model's footprint along W, and the volume IoU. Made
// once for an arrangement's slices and cylinders, and kept while they are the same (the
// graze and split repairs measure again after moving patches; a FreeCAD Thickness edit takes
// the cylinders of the design before it): fandisk's redesign, about 15 of its quality's 22 ms.
struct QualityBase {
  Region2d uSlices, vSlices;
  Region2d footprint;
  double volumeIou = 0;
};

QualityBase qualityBase(const SliceSet& u, const SliceSet& v, const std::vector<Cylinder>& uCylinders,
                        const std::vector<Cylinder>& vCylinders);

// `base` is qualityBase() of the same slices and cylinders.
Quality measureQuality(const QualityBase& base, const SliceSet& u, const SliceSet& v,
                       const std::vector<Cylinder>& uCylinders, const std::vector<Cylinder>& vCylinders,
                       const Scaffold& scaffold);

double iou(const Region2d& a, const Region2d& b);

}  // namespace sliceform
