// SPDX-License-Identifier: LGPL-2.1-or-later
// The assembled sliceform for 3D viewers: binary glTF (.glb). Each patch is one node named
// "patch N", its outline (within 0.01 mm of the exact face) triangulated, in metres with
// glTF's Y up (our Z up becomes Y), two-sided and in its family's paper colour.
#pragma once

#include <string>
#include <vector>

#include "output/assembly_png.hpp"

namespace sliceform {

// Written atomically. `panels` are assemblyPanels(): the patches' outlines at the fold
// pose, in mm, with their families. Throws Io.
void writeGltf(const std::vector<Panel3>& panels, const std::string& path);

}  // namespace sliceform
