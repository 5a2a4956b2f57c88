// SPDX-License-Identifier: LGPL-2.1-or-later
// Everything a maker needs from a design, written into one folder: the sheets (PDF, SVG,
// DXF, PNG), the 3D assembly (STEP, BREP, glTF, PNG) and report.json with timings.json.
// Shared by the CLI and the FreeCAD workbench so both write the same files.
#pragma once

#include <TopoDS_Shape.hxx>

#include <functional>
#include <future>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "pipeline/design.hpp"

namespace sliceform {

struct DesignFiles {
  std::vector<std::string> written;  // file names, in the order written
  std::vector<std::string> removed;  // sheet files an earlier, longer run left behind
};

// Writes a design's files into a folder. The STEP assembly is the slowest file and
// single-threaded (seconds for a mesh's polygon patches: OCCT's writer is quadratic in the
// edges of a face), so it is written on a thread of its own, started as soon as the
// patches are final (start(), from runDesign's PatchesReady) and so beside the layout and
// the other files; finish() writes the others and waits for it.
//
// Each file goes to a temporary name first and is renamed, so a failure leaves the earlier
// file whole. Sheet files beyond this design's sheet count (sheet-N.svg/.dxf only) are
// removed so a stale sheet is never cut by mistake. timings.json, written last, holds
// `before` (the caller's own stages, such as reading the model), the design's stages and
// what writing the files cost: "export files" is the wall time of writing all but the
// STEP file, on all cores, "export X, in parallel" each kind's own time within it (or, for
// STEP, on its own thread), "export STEP, waiting for it" what the STEP file added at the
// end. The stages not marked "in parallel" add up to the wall time. Throws Io.
class DesignFilesWriter {
 public:
  DesignFilesWriter(std::string folder, double foldAngleDegrees);
  ~DesignFilesWriter();  // waits for the STEP thread
  DesignFilesWriter(const DesignFilesWriter&) = delete;
  DesignFilesWriter& operator=(const DesignFilesWriter&) = delete;

  // Starts writing assembly.step; the design's arrangement and patches are final. A design
  // in the frame begun already changes nothing; one in another frame (the layout of the
  // first failed, and the direction search went on) replaces it, as discard() then start().
  void start(const Design& design);
  // Drops what start() began (the caller goes on with another design): waits for the STEP
  // thread and removes its file.
  void discard();
  // Writes the other files (starting the STEP file first if start() was not called).
  DesignFiles finish(const Model& model, const DesignParams& params, const Design& design,
                     const std::vector<StageTime>& before = {});

 private:
  std::string folder_;
  double foldAngle_;
  TopoDS_Shape assembly_;     // the patches at the fold pose, from start()
  std::string stepFile_;      // where the STEP thread writes, renamed by finish()
  Vec3 begunU_, begunV_;      // the frame of the design start() began
  bool madeFolder_ = false;   // the folder did not exist before start()
  std::future<double> step_;  // ms the STEP file took
};

// start() and finish() at once.
DesignFiles writeDesignFiles(const Model& model, const DesignParams& params, const Design& design,
                             const std::string& folder, double foldAngleDegrees,
                             const std::vector<StageTime>& before = {});

// "sheet-3.dxf" for sheet index 2.
std::string sheetFileName(int sheet, const char* extension);

}  // namespace sliceform
