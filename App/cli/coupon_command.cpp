// SPDX-License-Identifier: LGPL-2.1-or-later
// `sliceform coupon -o DIR`: the fit test coupon (output/coupon.hpp) for the material and
// cutter settings a design would use, in every sheet format the design writes.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/commands.hpp"
#include "frames/stabilize.hpp"
#include "output/coupon.hpp"

namespace sliceform::cli {
namespace {

struct CouponOptions {
  std::string output;
  SlotParams slots;
  HingeRules rules;
  StabilizeOptions spacing;
};

void runCoupon(CouponOptions o) {
  checkSlotParams(o.slots);
  o.rules.slotWidth = o.slots.width();
  const double spacing = minPatchSpacing(o.spacing, o.rules);
  const Coupon c = makeCoupon(o.slots, o.rules.minSlotEdgeDistance, spacing);
  std::filesystem::create_directories(o.output);
  writeCoupon(c, o.output);
  std::printf("coupon     %zu strips on %.0f x %.0f mm: pairs at clearances", c.strips.size(), c.sheet.width,
              c.sheet.height);
  for (size_t k = 0; k + 2 < c.strips.size(); k += 2) std::printf(" %s", c.strips[k].text.c_str());
  std::printf(" mm; E: slot %.1f mm from the end; F: %.1f mm of paper between two slots\n",
              o.rules.minSlotEdgeDistance, spacing - o.slots.width());
  std::printf("wrote      %s: coupon.pdf, coupon.svg, coupon.dxf, coupon.png, coupon.json\n",
              o.output.c_str());
  std::printf(
      "use        cut it, slide each pair together; design with --clearance of the pair that holds "
      "snugly without bending; if E or F tears, raise --min-slot-edge-distance or --min-spacing\n");
}

}  // namespace

void addSlotOptions(CLI::App* cmd, SlotParams& slots, HingeRules& rules, StabilizeOptions& spacing) {
  addParameter(cmd, "thickness", slots.thickness);
  addParameter(cmd, "clearance", slots.clearance);
  addParameter(cmd, "kerf", slots.kerf);
  addParameter(cmd, "min_slot_edge_distance", rules.minSlotEdgeDistance);
  addParameter(cmd, "min_spacing", spacing.minSpacing);
}

Run addCouponCommand(CLI::App& app) {
  auto o = std::make_shared<CouponOptions>();
  CLI::App* cmd = app.add_subcommand(
      "coupon",
      "Write a fit test coupon: pairs of slotted strips at clearances around --clearance, each engraved "
      "with its clearance, and strips that test the slot-edge distance (E) and the paper between slots (F). "
      "Cut it from the design's material on the design's cutter; the pair that slides together snugly names "
      "the --clearance to design with.");
  cmd->add_option("-o,--output", o->output, "folder for coupon.pdf, .svg, .dxf, .png and .json")->required();
  addSlotOptions(cmd, o->slots, o->rules, o->spacing);
  return [o] { runCoupon(*o); };
}

}  // namespace sliceform::cli
