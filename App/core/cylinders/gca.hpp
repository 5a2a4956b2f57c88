// SPDX-License-Identifier: LGPL-2.1-or-later
// Generalized cylinder approximation (§4.1.1): the patches of each Reeb edge are split
// into the fewest runs of consecutive slices whose cylinders (the union of the run's
// patches swept along the run) stay within tauA of the part they replace.
#pragma once

#include <utility>
#include <vector>

#include "geometry/region2d.hpp"
#include "reeb/reeb_graph.hpp"
#include "slicing/slice_set.hpp"

namespace sliceform {

struct Cylinder {
  Family family = Family::U;
  int reebEdge = 0;
  int firstSlice = 0, lastSlice = 0;  // the slices it covers, inclusive (its span)
  Region2d section;                   // union of its slices: every patch taken from it
  double error = 0;                   // err(i, j) of eq. (1), mm³
};

// Groups [i, j] (indices into `patches`, inclusive) of the optimal partition: the fewest
// groups whose summed error (1) is at most tauA times the volume of the patches,
// ds * sum(area). Decision: tauA is relative to the volume of the part being split, so
// the same tauA means the same fidelity for a small horn and a large body.
// Every group spans at least `minRun` slices (the whole edge when it is shorter): the
// patches of two neighbouring cylinders must lie the spacing rule apart, which two
// cylinders of a slice or two cannot give. Where no such partition fits the budget, the
// one with the least error is taken.
std::vector<std::pair<int, int>> partitionPatches(const std::vector<Region2d>& patches, double ds,
                                                  double tauA, int minRun = 1);

// Cylinders of every edge of a (simplified) Reeb graph.
std::vector<Cylinder> approximateCylinders(const ReebGraph& graph, Family family, double ds, double tauA,
                                           int minRun = 1);

// Volume error (1) of the cylinder of patches[i..j]: ds * sum(area(union) - area(p_k)).
double cylinderError(const std::vector<Region2d>& patches, int i, int j, double ds);

}  // namespace sliceform
