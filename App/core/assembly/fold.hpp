// SPDX-License-Identifier: LGPL-2.1-or-later
// The assembled sliceform at a fold angle (Prop. 1). Every patch stays parallel to its
// family while the lattice folds, so the pose is a closed form. In the cross-section plane
// a point is t1 V + t2 e2, with e2 = U when popped up (theta = 90°); at angle theta,
// e2 = cos(theta) V + sin(theta) U. So U-patches translate, by u (sin theta - 1) U +
// u cos(theta) V, and V-patches rotate about the W axis through v V by 90° - theta. At a
// small angle the sliceform lies nearly flat.
#pragma once

#include <TopoDS_Shape.hxx>
#include <gp_Trsf.hxx>

#include <string>
#include <vector>

#include "arrangement/arrange.hpp"
#include "exact/patch_faces.hpp"

namespace sliceform {

// Where patch `patch` goes at fold angle theta (degrees, in (0, 90]).
gp_Trsf foldTransform(const Arrangement& arrangement, int patch, double thetaDegrees);

// All patches at fold angle theta, as one compound of faces.
TopoDS_Shape assemble(const Arrangement& arrangement, const std::vector<PatchFace>& patches,
                      double thetaDegrees);

// The ids of the patches assemble() puts in the compound, in its order.
std::vector<std::string> assembledIds(const Arrangement& arrangement, const std::vector<PatchFace>& patches);

// Written atomically; the format is the file's extension: .step / .stp or .brep. A STEP
// file names each face's part by `names` (planarFacesStep).
void writeShape(const TopoDS_Shape& shape, const std::string& path,
                const std::vector<std::string>& names = {});

}  // namespace sliceform
