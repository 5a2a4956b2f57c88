// SPDX-License-Identifier: LGPL-2.1-or-later
// What choosing the slicing directions tried (pipeline/directions), for the report.
#pragma once

#include <string>
#include <vector>

#include "arrangement/arrange.hpp"
#include "geometry/vec.hpp"
#include "quality/quality.hpp"

namespace sliceform {

struct FrameTrial {
  std::string name;     // "Z up, 15°", "principal 2 up, 0°"
  Vec3 u, v;            // W = u x v is up
  int axis = 0;         // which up axis it turns about, in the order tried
  double turn = 0;      // degrees about it, from the axis's first direction
  bool stands = false;  // with W up, the centre of mass is above the base footprint
  // The estimate: the arrangement at a few slices.
  Quality estimate;
  int estimatePatches = 0;
  double score = 0;     // kDirections objective on the estimate; -1 when it failed
  std::string failure;  // why the estimate or the design failed, if it did
  // The full design, for the best few.
  bool designed = false;
  bool buildable = false;
  Quality quality;
  bool laidOut = false;  // only designs still in the running are laid out: `sheets` is 0 if not
  int patches = 0, sheets = 0;
  double designScore = 0;  // the score less the sheets' cost, when laid out
};

struct DirectionChoice {
  bool automatic = false;  // false: the directions were given
  std::vector<FrameTrial> trials;
  int chosen = -1;
  std::string why;  // one sentence for the summary
  // What the estimates were made from (the arrangement parameters at the estimates' slices,
  // directions left out: they read nothing else), and whether they were taken from an
  // earlier design's choice rather than made.
  ArrangementParams estimatedWith;
  bool estimatesTaken = false;
};

}  // namespace sliceform
