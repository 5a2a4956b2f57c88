// SPDX-License-Identifier: LGPL-2.1-or-later
#include "pipeline/design.hpp"

#include <chrono>

namespace sliceform {
namespace {

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

Design runDesign(const Model& model, DesignParams params, const Progress& progress,
                 const PatchesReady& patchesReady) {
  // Hinges must hold with the slot cut: the paper beside it is measured from its walls.
  checkSlotParams(params.slots);
  params.arrangement.hinges.slotWidth = params.slots.width();
  Design d;
  if (progress) progress("arrangement");
  d.arrangement = arrange(model, params.arrangement);
  d.timings = d.arrangement.timings;
  const RealizationInput input = realizationInput(d.arrangement, model.meshDeflection);
  d.realization = timed(d.timings, "realization", progress, [&] { return realize(input, params.slots); });
  d.patches = timed(d.timings, "exact patches", progress,
                    [&] { return exactPatches(model, d.arrangement, d.realization); });
  d.emitted = timed(d.timings, "check", progress, [&] {
    std::vector<Region2d> outlines;
    for (const PatchFace& p : d.patches) outlines.push_back(p.outline);
    return checkEmitted(input, outlines);
  });
  d.certificate = timed(d.timings, "certificate again", progress, [&] {
    std::vector<BarPatch> bars;
    for (const ScaffoldPatch& p : d.arrangement.scaffold.patches) bars.push_back({p.family, p.position});
    std::vector<PinHinge> pins;
    const auto& hinges = d.arrangement.scaffold.hinges;
    for (size_t h = 0; h < hinges.size(); ++h)
      if (hinges[h].holds && d.realization.meets[h]) pins.push_back({hinges[h].u, hinges[h].v});
    return certify(bars, pins);
  });
  if (patchesReady) patchesReady(d);
  d.layout = timed(d.timings, "layout", progress, [&] { return layOut(d, params.sheet); });
  return d;
}

}  // namespace sliceform
