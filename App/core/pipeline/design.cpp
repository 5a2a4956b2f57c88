// SPDX-License-Identifier: LGPL-2.1-or-later
#include "pipeline/design.hpp"

#include "support/error.hpp"

#include <chrono>
#include <sstream>

namespace sliceform {
namespace {

// The patches in pieces (or pairs that lost their holding hinges) that SplitRepair::WhenFew
// repairs at most. Of the 42 models (occt-misc and meshes) whose file axes or chosen frame
// needed the repair, it mended one patch in its 24 searches: cow.obj's file axes at the
// 18th, occ/Top.brep's chosen frame at the 19th; occ/Motor-c.brep's file axes one of four at
// the 7th and none after; occ/Top.brep's file axes none of 11 (6 s of searches).
constexpr int kFewBroken = 2;

template <class Fn>
auto timed(std::vector<StageTime>& timings, const char* stage, const Progress& progress, Fn&& fn) {
  if (progress) progress(stage);
  const auto start = std::chrono::steady_clock::now();
  auto result = fn();
  timings.push_back(
      {stage, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count()});
  return result;
}

}  // namespace

Design runDesign(const Model& model, const DesignParams& params, const Progress& progress,
                 const PatchesReady& patchesReady, const Deadline* deadline, const Design* earlier) {
  Design d = designPatches(model, params, progress, deadline, earlier);
  if (patchesReady) patchesReady(d);
  layOutDesign(d, params.sheet, progress);
  return d;
}

void layOutDesign(Design& d, const SheetSpec& sheet, const Progress& progress) {
  d.layout = timed(d.timings, "layout", progress, [&] { return layOut(layoutInput(d), sheet); });
}

Design designPatches(const Model& model, DesignParams params, const Progress& progress,
                     const Deadline* runDeadline, const Design* earlier, SplitRepair repair) {
  // Hinges must hold with the slot cut: the paper beside it is measured from its walls.
  checkSlotParams(params.slots);
  if (!(params.timeLimit >= 0))
    throw Error(ErrorKind::BadParameter, "the time limit must be 0 (none) or more seconds");
  const Deadline own(runDeadline ? 0 : params.timeLimit);
  const Deadline& deadline = runDeadline ? *runDeadline : own;
  params.arrangement.hinges.slotWidth = params.slots.width();
  Design d;
  d.timeLimit = params.timeLimit;
  if (progress) progress("arrangement");
  d.arrangement = arrange(model, params.arrangement, earlier ? &earlier->arrangement : nullptr);
  d.timings = d.arrangement.timings;
  if (progress) progress("realization");  // grazes and the slot search: one stage to the user
  d.grazes = timed(d.timings, "grazes", {},
                   [&] { return avoidGrazes(d.arrangement, params.slots, model.meshDeflection, deadline); });
  d.realization = timed(d.timings, "realization", {}, [&] {
    Realization r = realize(realizationInput(d.arrangement, model.meshDeflection), params.slots, deadline);
    d.grazes.splitLeft = repair == SplitRepair::WhenFew && r.splitPatches + r.lostPins > kFewBroken;
    if (!d.grazes.splitLeft)
      repairSplits(d.arrangement, r, d.grazes, params.slots, model.meshDeflection, deadline);
    return r;
  });
  const RealizationInput input = realizationInput(d.arrangement, model.meshDeflection);
  // The earlier design's exact sections where the cylinders are its own.
  if (earlier && d.arrangement.stagesTaken == 3) d.exactSections = earlier->exactSections;
  d.patches = timed(d.timings, "exact patches", progress, [&] {
    // A design the slot search left broken is refused whatever its faces are: it keeps the
    // polygons the search checked, and the time its exact sections would take goes to the
    // frames the CLI and the direction search try next (occ/Top.brep at the file's axes:
    // 11 patches in pieces, then 13-32 s of exact sections before the next frame began).
    const Realization& r = d.realization;
    if (model.kind == SourceKind::Brep &&
        (r.splitPatches > 0 || r.lostPins > 0 || r.interlocks.remaining > 0)) {
      std::vector<PatchFace> polygons;
      for (size_t k = 0; k < d.arrangement.scaffold.patches.size(); ++k)
        polygons.push_back(polygonPatch(d.arrangement, r, static_cast<int>(k), false));
      return polygons;
    }
    return exactPatches(model, d.arrangement, d.realization, deadline, &d.exactSections);
  });
  const std::vector<ScaffoldHinge>& hinges = d.arrangement.scaffold.hinges;
  d.emitted = timed(d.timings, "check", progress, [&] {
    const auto outlines = [&] {
      std::vector<Region2d> out;
      for (const PatchFace& p : d.patches) out.push_back(p.outline);
      return out;
    };
    Emitted e = checkEmitted(input, outlines(), params.slots);
    // An exact face can break what its polygon keeps: material the polygon section lacks
    // runs into a partner with no slot, or a Boolean leaves the paper cut differently. A
    // simplified polygon can too: within kOutlineDeflection a bridge the search kept may
    // open, or a sliver it cut away come back. Such a patch is emitted as the very polygon
    // the search checked, and the outlines are checked again, until none is left to
    // replace (each pass replaces at least one, and a replaced one for good). A partner
    // of a patch that broke a rule waits for the check after it (occ/MODERN_Exhaust_1.brep:
    // U0 in pieces lost its hinge with V1, whose exact face went too).
    // A pass counts again only the replaced patches' pieces (occ/Top.brep: 3 passes, 11 and
    // 13 of 110 patches replaced).
    std::vector<char> replaced(d.patches.size(), 0);
    for (std::vector<int> next;
         !(next = patchesToReplace(e, hinges, d.realization.meets, replaced)).empty();) {
      std::vector<int> known = e.pieces;
      for (const int k : next) {
        d.exactReplaced += d.patches[k].exact ? 1 : 0;
        d.patches[k] = polygonPatch(d.arrangement, d.realization, k, false);
        replaced[k] = 1;
        known[k] = -1;
      }
      e = checkEmitted(input, outlines(), params.slots, &known);
    }
    return e;
  });
  d.certificate = timed(d.timings, "certificate again", progress, [&] {
    std::vector<BarPatch> bars;
    for (const ScaffoldPatch& p : d.arrangement.scaffold.patches) bars.push_back({p.family, p.position});
    std::vector<PinHinge> pins;
    for (size_t h = 0; h < hinges.size(); ++h)
      if (hinges[h].holds && d.emitted.meets[h]) pins.push_back({hinges[h].u, hinges[h].v});
    return certify(bars, pins);
  });
  return d;
}

LayoutInput layoutInput(const Design& d) {
  return {d.arrangement, d.realization, d.emitted.meets, d.patches};
}

std::vector<std::string> designProblems(const Design& d) {
  std::vector<std::string> out;
  const Arrangement& a = d.arrangement;
  const Emitted& e = d.emitted;
  const auto id = [&](int k) { return patchId(a.scaffold, k); };
  if (d.realization.timedOut || d.grazes.timedOut || d.grazes.splitTimedOut) {
    std::ostringstream s;
    s << "the time limit (" << d.timeLimit << " s) ran out while "
      << (d.realization.timedOut ? "searching for slots"
          : d.grazes.timedOut    ? "moving patches off grazes"
                                 : "moving or taking out patches the slot search left in pieces")
      << "; this is the best design found (try a larger --time-limit, or fewer --slices)";
    out.push_back(s.str());
  }
  if (!a.certificate.stable) out.push_back("the scaffold is not stable: " + a.certificate.reason);
  if (a.certificate.stable && !d.certificate.stable) {
    std::ostringstream s;
    s << "the slotted design is not stable (nullity " << d.certificate.nullity
      << "): " << d.realization.lostPins << " pair(s) lost every holding hinge to the slots";
    out.push_back(s.str());
  }
  // A few ids say where; the count says how many.
  const auto where = [&](const std::vector<int>& patches) {
    std::string s;
    for (size_t i = 0; i < patches.size() && i < 6; ++i) s += (i ? ", " : "") + id(patches[i]);
    return patches.size() > 6 ? s + ", ..." : s;
  };
  if (e.interlocks > 0) {
    std::vector<int> pairs;
    for (const auto& [u, v] : e.interlocked) pairs.insert(pairs.end(), {u, v});
    out.push_back(std::to_string(e.interlocks) + " interlocked loop pair(s) (" + where(pairs) +
                  "): the slot search found no slots that free them (try other --u/--v directions)");
  }
  if (e.splitPatches > 0) {
    std::ostringstream s;
    s << e.splitPatches << " patch(es) in pieces (" << where(e.split)
      << "): their slots leave paper narrower than " << 2 * slotNeck(d.realization.params, 0)
      << " mm between them or to the edge (try a larger --min-spacing for "
      << "fewer patches farther apart, a larger --size for wider paper, or a thinner --thickness)";
    out.push_back(s.str());
  }
  if (!e.collisions.empty()) {
    std::ostringstream s;
    s << e.collisions.size()
      << " U/V pair(s) overlap along their common line with no slot between them (up to " << e.worstOverlap
      << " mm, e.g. " << id(e.collisions.front().first) << " and " << id(e.collisions.front().second) << ")";
    out.push_back(s.str());
  }
  if (tooClose(e, a.minSpacing)) {
    std::ostringstream s;
    s << id(e.closest.first) << " and " << id(e.closest.second) << " are " << e.minPatchSpacing
      << " mm apart where the spacing rule asks " << a.minSpacing << " mm (try a larger --size)";
    out.push_back(s.str());
  }
  return out;
}

}  // namespace sliceform
