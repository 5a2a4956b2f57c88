// SPDX-License-Identifier: LGPL-2.1-or-later
// Stabilization (§4.2): chooses patches so that the scaffold is stable and every cylinder
// that needs one gets a patch.
//
// Decision (deviation from Alg. 1/2, written down in docs/decisions.md): the paper chains
// stable frame sets through shared frames (Def. 12), but two stable 2x2 sets sharing one
// patch still swing against each other (nullity 2). We grow one rigid scaffold instead:
// start from a 2x2 grid (Claims 1 and 2), and add a patch only where it hinges, with
// hinges that hold, on at least two patches of the other family at different positions.
// Such a patch cannot move but with the fold, so the scaffold stays stable by induction;
// support patches (the paper's alpha-supports) are added where a needed cylinder cannot
// reach two patches yet. The certificate checks the result independently.
#pragma once

#include <vector>

#include "cylinders/gca.hpp"
#include "frames/hinge_table.hpp"
#include "frames/scaffold.hpp"

namespace sliceform {

struct StabilizeOptions {
  Scheme scheme = Scheme::Both;
  double maxSpacing = 0;  // mm; > 0 adds patches in long cylinders (Fig. 16b), 0 = off
  // mm; two patches of one family whose outlines overlap seen along their normal are at
  // least this far apart, so their slots on a common partner leave paper between them.
  // 0 = the least that keeps min_slot_edge_distance there (minPatchSpacing()).
  double minSpacing = 0;
};
inline bool operator==(const StabilizeOptions& a, const StabilizeOptions& b) {
  return a.scheme == b.scheme && a.maxSpacing == b.maxSpacing && a.minSpacing == b.minSpacing;
}

// The spacing rule in force: `options.minSpacing`, or when 0, one slot width plus the
// paper the design keeps beside any slot. Throws BadParameter for a value below that.
double minPatchSpacing(const StabilizeOptions& options, const HingeRules& rules);
// The fewest slices of `interval` mm that are `spacing` mm apart (at least 1).
int slicesApart(double spacing, double interval);

Scaffold stabilize(const SliceSet& u, const SliceSet& v, const std::vector<Cylinder>& uCylinders,
                   const std::vector<Cylinder>& vCylinders, const HingeTable& table,
                   const StabilizeOptions& options);

// Every hinge segment between the scaffold's U- and V-patches, marked holding or not.
void findHinges(Scaffold& scaffold, const HingeTable& table);

// Whether two sections of one family overlap seen along its normal (holes filled: a patch
// seen through another's hole still has its slots beside the other's on a partner).
bool stackedSections(const Region2d& a, const Region2d& b);

// Takes patch k out and finds the hinges again; its cylinder is listed as uncovered when no
// other patch covers it. Patches after k move down by one. Stability is the caller's.
void dropPatch(Scaffold& scaffold, const HingeTable& table, int k);

// Moves patch k to another slice of its cylinder and finds the hinges again; false, and
// the scaffold unchanged, when the slice is outside the cylinder, taken, or closer than
// minSpacing to a stacked patch. Stability is the caller's to check.
bool movePatch(Scaffold& scaffold, const SliceSet& u, const SliceSet& v,
               const std::vector<Cylinder>& uCylinders, const std::vector<Cylinder>& vCylinders,
               const HingeTable& table, double minSpacing, int k, int slice);

}  // namespace sliceform
