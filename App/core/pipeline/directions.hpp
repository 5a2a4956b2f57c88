// SPDX-License-Identifier: LGPL-2.1-or-later
// Slicing directions chosen for the model (`--directions auto`). Decision (docs/decisions.md,
// "Directions"): candidate frames are the model's principal axes and the file's axes, each
// axis in turn up, the two families turned about it; each is estimated by its arrangement at
// a few slices, the best are designed in full, and the buildable design that scores best
// wins. Every frame tried and its score go to report.json.
#pragma once

#include "pipeline/design.hpp"

namespace sliceform {

// Slices a direction for the estimates: enough for the Reeb graph and the cylinders to
// show the shape, few enough that a dozen frames cost less than one design.
constexpr int kEstimateSlices = 40;

// The frames to try, before any is estimated: for each of the 6 up axes (3 principal, 3 of
// the file) the families at 0° and 45° about it, W's sign chosen so the model stands.
std::vector<FrameTrial> candidateFrames(const Model& model);

// Whether the model stands with `up` up: its centre of mass over its base footprint.
bool standsUp(const Mesh& mesh, const Vec3& up);

// The design in the best frame; `choice` gets every frame tried. `params.arrangement.u/v`
// are ignored. Throws the best frame's error when no frame gives a design. `earlier`: a
// design of the same model, whose first stages the full design takes where they match
// (runDesign), as when a FreeCAD edit keeps the frame chosen before. `made`: a design
// of the same model with these parameters in one frame, not laid out (designPatches; the
// file's axes the CLI tried first): a trial in exactly its frame takes a copy of it instead
// of designing it again.
Design designInBestFrame(const Model& model, DesignParams params, DirectionChoice& choice,
                         const Progress& progress = {}, const PatchesReady& patchesReady = {},
                         const Deadline* deadline = nullptr, const Design* earlier = nullptr,
                         const Design* made = nullptr);

}  // namespace sliceform
