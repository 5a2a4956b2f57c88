// SPDX-License-Identifier: LGPL-2.1-or-later
// The whole pipeline from a model to a design that can be cut: arrangement (§4),
// realization (§5), exact patch faces, and a last check of what is emitted (verify/emitted:
// real hinges, collisions, interlocks, split patches, spacing; an exact face that breaks a
// rule its polygon keeps is replaced by the polygon), and the certificate on the hinges
// that are left; then
// the layout: patches flattened, labelled and nested onto sheets. Each stage is timed;
// `progress` hears of each stage as it starts (kDesignStages of them).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "arrangement/arrange.hpp"
#include "exact/patch_faces.hpp"
#include "layout/layout.hpp"
#include "pipeline/frame_trials.hpp"
#include "realization/grazes.hpp"
#include "realization/realize.hpp"
#include "support/deadline.hpp"
#include "verify/emitted.hpp"

namespace sliceform {

struct DesignParams {
  ArrangementParams arrangement;
  SlotParams slots;
  SheetSpec sheet;
  // Seconds the searches may take in all, from the start of the run (0: no limit). A last
  // resort: past it the design is the best found, and it is not called buildable.
  double timeLimit = 60;
};

struct Design {
  Arrangement arrangement;
  GrazeRepair grazes;  // patches moved off hinges no slot can cut
  Realization realization;
  std::vector<PatchFace> patches;  // exact faces at the popped-up pose
  ExactSections exactSections;     // what the patches were cut from (BRep sources)
  Emitted emitted;                 // the fabrication contract, checked on the emitted outlines
  int exactReplaced = 0;           // exact faces that broke it, emitted as the search's polygons
  Certificate certificate;         // again, on the hinges whose slotted patches still meet
  SheetLayout layout;              // flat, labelled patches nested onto sheets
  std::vector<StageTime> timings;  // every stage, the arrangement's included
  double timeLimit = 0;            // seconds the searches had (DesignParams::timeLimit)
  DirectionChoice directions;      // the frames tried, when the directions were chosen
};

using Progress = std::function<void(const char* stage)>;
constexpr int kDesignStages = 6;
// Hears of the design once its patches are built and checked, before the layout: the 3D
// assembly is then final, so its files can be written while the sheets are laid out. The
// design is the pipeline's own, about to change: copy what is needed, keep no reference.
// designInBestFrame may hear of a design in another frame after one whose layout failed:
// the later one replaces it (DesignFilesWriter::start).
using PatchesReady = std::function<void(const Design& design)>;

// `deadline`: the run's, when it designs more than once (other frames); by default
// params.timeLimit from now. `earlier`: a design of the same model, whose first stages are
// taken where their inputs are the same (arrange()).
Design runDesign(const Model& model, const DesignParams& params, const Progress& progress = {},
                 const PatchesReady& patchesReady = {}, const Deadline* deadline = nullptr,
                 const Design* earlier = nullptr);

// How far designPatches repairs the patches the slot search left in pieces (repairSplits):
// always; or only where few are, for a frame other frames follow when it cannot be built
// (the CLI's file axes, no one's choice). The repair mends about one patch in its searches
// (kFewBroken), each a whole slot search: with more in pieces, the time goes to the other
// frames, and the design says so (GrazeRepair::splitLeft).
enum class SplitRepair { Always, WhenFew };

// runDesign in its two parts, for a caller that picks among designs before laying one out
// (designInBestFrame): every stage up to the layout (`layout` left empty; designProblems
// reads nothing of it), then the layout.
Design designPatches(const Model& model, DesignParams params, const Progress& progress = {},
                     const Deadline* deadline = nullptr, const Design* earlier = nullptr,
                     SplitRepair repair = SplitRepair::Always);
void layOutDesign(Design& design, const SheetSpec& sheet, const Progress& progress = {});

// What the layout reads of it (layOut, flattenPatch): refers to the design's own members.
LayoutInput layoutInput(const Design& design);

// Why the design cannot be built, one clause per broken rule naming what helps; empty when
// it can. The CLI's exit code and the FreeCAD feature's state both come from it.
std::vector<std::string> designProblems(const Design& design);

}  // namespace sliceform
