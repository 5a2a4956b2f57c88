// SPDX-License-Identifier: LGPL-2.1-or-later
// Mesh slicer: cuts a closed triangle mesh with parallel planes, the way 3D-printing
// slicers do: every triangle that crosses a plane gives one segment, segments are chained
// through the mesh edges they cross into closed loops, and the loops become a Region2d.
#pragma once

#include <vector>

#include "model/mesh.hpp"
#include "slicing/slice_set.hpp"

namespace sliceform {

struct MeshSliceStats {
  size_t segments = 0;
  size_t loops = 0;
  size_t openChains = 0;         // always 0 when sliceMesh returns: it throws instead
  size_t inconsistentLoops = 0;  // loops whose triangles disagree on orientation
};

// `count` uniform positions (cell centres) across the mesh's extent along the frame normal.
std::vector<double> slicePositions(const Mesh& mesh, const SliceFrame& frame, int count);

// One slice per position. Throws BadInput if a plane meets the mesh in a chain that does
// not close (the mesh has a hole there). Uses every core.
SliceSet sliceMesh(const Mesh& mesh, const SliceFrame& frame, const std::vector<double>& positions,
                   MeshSliceStats* stats = nullptr);

}  // namespace sliceform
