// SPDX-License-Identifier: LGPL-2.1-or-later
// Whether partitionPatches (gca.cpp) may stop measuring runs: its answer on the runs
// measured so far, checked against lower bounds of the runs not measured yet.
#pragma once

#include <utility>
#include <vector>

namespace sliceform {

// The runs of an edge's patches measured so far, in partitionPatches' terms: err(i, j) and
// the area of the run's union for j from i to last[i].
struct MeasuredRuns {
  const std::vector<std::vector<double>>& err;        // [i][j], infinite beyond last[i]
  const std::vector<std::vector<double>>& unionArea;  // [i][j - i]
  const std::vector<int>& last;
  const std::vector<char>& open;          // per row: measured short of where the budget stops it
  const std::vector<double>& areaBefore;  // the patches' areas summed, before each patch
  double ds, budget;
  int minRun;
};

// What partitionPatches' answer on the runs measured needs before it is the very one it
// gives with every run measured (each row until its error passes the budget): the runs
// (start, end) not measured that could change it, every open row's rest when it needs
// them all; none when it stands. The answer is m groups, the first count that fits the
// budget or, where none does, the first with the least error; m = 0 asks whether none
// fits. best[g][i] is the DP's least error of patches i..n-1 in g groups, and
// choice[g][i] where the first of them ends.
std::vector<std::pair<int, int>> runsToMeasure(const MeasuredRuns& at, int m,
                                               const std::vector<std::vector<double>>& best,
                                               const std::vector<std::vector<int>>& choice);

}  // namespace sliceform
