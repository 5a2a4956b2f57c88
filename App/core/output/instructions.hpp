// SPDX-License-Identifier: LGPL-2.1-or-later
// instructions.pdf: the assembly booklet. A cover with the finished sliceform, the parts by
// sheet and the tools; then one numbered step per patch in the design's assembly order,
// six to a page, each naming the patch, the partners its slots go onto (and whether its
// slot opens at the top or the bottom), with a picture of the assembly so far and the new
// patch in the highlight colour. Pictures share one view and scale, so they line up.
#pragma once

#include <string>
#include <vector>

#include "output/assembly_png.hpp"
#include "pipeline/design.hpp"

namespace sliceform {

// What one step says: the patch and, per partner already placed, how its slot goes on.
struct AssemblyStep {
  int patch = -1;
  std::string id;
  std::vector<std::string> fromTop, fromBottom, through, partnerCuts;  // partner ids
};
std::vector<AssemblyStep> assemblySteps(const Design& design);

// Steps on one page of the booklet.
constexpr int kStepsPerPage = 6;

// Written atomically with cairo. `title` names the model; `whole` is the finished
// sliceform for the cover (drawAssembly of `panels`: the picture assembly.png shows, drawn
// once for both). Throws Io.
void writeInstructionsPdf(const Design& design, const std::vector<Panel3>& panels, const Picture& whole,
                          const std::string& title, const std::string& path);

}  // namespace sliceform
