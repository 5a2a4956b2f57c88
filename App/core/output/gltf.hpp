// SPDX-License-Identifier: LGPL-2.1-or-later
// The assembled sliceform for 3D viewers: binary glTF (.glb). Each patch is one node named
// "patch N" with its faces meshed finely enough for paper curves, in metres with glTF's Y up
// (our Z up becomes Y), two-sided and in its family's paper colour.
#pragma once

#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

#include "arrangement/arrange.hpp"
#include "exact/patch_faces.hpp"

namespace sliceform {

// Written atomically. `assembly` is what assemble() returns: a compound with one sub-shape
// per patch, in mm. `families`, if given, holds 0 (U) or 1 (V) per sub-shape in the same
// order (see assemblyFamilies); without it every patch gets the U colour. Throws Io.
void writeGltf(const TopoDS_Shape& assembly, const std::string& path, const std::vector<int>& families = {});

// The family (0 = U, 1 = V) of each sub-shape of assemble(arrangement, patches, theta): one
// per patch that has faces, in patch order.
std::vector<int> assemblyFamilies(const Arrangement& arrangement, const std::vector<PatchFace>& patches);

}  // namespace sliceform
