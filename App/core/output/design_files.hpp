// SPDX-License-Identifier: LGPL-2.1-or-later
// Everything a maker needs from a design, written into one folder: the sheets (PDF, SVG,
// DXF, PNG), the 3D assembly (STEP, BREP, glTF, PNG) and report.json with timings.json.
// Shared by the CLI and the FreeCAD workbench so both write the same files.
#pragma once

#include <string>
#include <vector>

#include "model/model.hpp"
#include "pipeline/design.hpp"

namespace sliceform {

struct DesignFiles {
  std::vector<std::string> written;  // file names, in the order written
  std::vector<std::string> removed;  // sheet files an earlier, longer run left behind
};

// Each file goes to a temporary name first and is renamed, so a failure leaves the earlier
// file whole. Sheet files beyond this design's sheet count (sheet-N.svg/.dxf only) are
// removed so a stale sheet is never cut by mistake. timings.json, written last, holds
// `before` (the caller's own stages, such as reading the model), the design's stages and
// what writing each file cost ("export ..."); the STEP file is written on a second thread,
// so "export STEP, in parallel" is its own time and "export STEP, waiting for it" what it
// added to the run (the others add up to the wall time). Throws Io.
DesignFiles writeDesignFiles(const Model& model, const DesignParams& params, const Design& design,
                             const std::string& folder, double foldAngleDegrees,
                             const std::vector<StageTime>& before = {});

// "sheet-3.dxf" for sheet index 2.
std::string sheetFileName(int sheet, const char* extension);

}  // namespace sliceform
