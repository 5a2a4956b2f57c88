// SPDX-License-Identifier: LGPL-2.1-or-later
// `sliceform design MODEL -o DIR`: arranges a stable sliceform scaffold (§4), slots it so
// it can be assembled (§5), builds the exact patches, and prints a summary: patches,
// hinges, the certificate, interlocks, slots, quality, time per stage. With -o it writes
// report.json, timings.json and the 3D assembly (assembly.step, assembly.brep) into DIR.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <filesystem>

#include <unistd.h>

#include "assembly/fold.hpp"
#include "cli/commands.hpp"
#include "output/report_json.hpp"
#include "pipeline/design.hpp"
#include "support/error.hpp"

namespace sliceform::cli {
namespace {

struct DesignOptions : ModelOptions {
  std::string output;
  double size = 150;
  std::string scheme = "both";
  std::string slotEnd = "square";
  std::string uSlots = "up";
  double foldAngle = 90;
  DesignParams params;
};

void printRealization(const Design& d, const DesignParams& params) {
  const Realization& r = d.realization;
  std::printf("interlocks %d found, %d repaired, %d remaining; %d cut-through(s); %d split patch(es)\n",
              r.interlocks.found, r.interlocks.repaired, d.emitted.interlocks, r.interlocks.cutThroughs,
              d.emitted.splitPatches);
  std::printf("slotted    stable %s (nullity %d); %d pair(s) lost every holding hinge\n",
              d.certificate.stable ? "yes" : "NO", d.certificate.nullity, r.lostPins);
  std::printf("slots      %.2f mm wide; smallest slot-to-edge distance %.2f mm; shortest hinge %.2f mm\n",
              params.slots.width(), r.minSlotEdgeDistance, r.shortestHinge);
  int exact = 0;
  for (const PatchFace& p : d.patches) exact += p.exact ? 1 : 0;
  std::printf("exact      %d of %zu patches from the BRep's exact sections, the others polygons\n", exact,
              d.patches.size());
  std::printf("assembly   %s:",
              r.assemblyChecked ? "order checked pairwise" : "ORDER NOT FREE of interlocks");
  for (const int k : r.assemblyOrder) std::printf(" %s", patchId(d.arrangement.scaffold, k).c_str());
  std::printf("\n");
}

void writeOutputs(const Model& model, const DesignParams& params, const Design& d, const DesignOptions& o) {
  std::filesystem::create_directories(o.output);
  const std::filesystem::path dir(o.output);
  writeJson(reportJson(model, params, d), (dir / "report.json").string());
  writeJson(timingsJson(d), (dir / "timings.json").string());
  const TopoDS_Shape assembly = assemble(d.arrangement, d.patches, o.foldAngle);
  writeShape(assembly, (dir / "assembly.step").string());
  writeShape(assembly, (dir / "assembly.brep").string());
  std::printf("wrote      %s: report.json, timings.json, assembly.step and assembly.brep at %g degrees\n",
              o.output.c_str(), o.foldAngle);
}

void runDesign(DesignOptions o) {
  if (!(o.foldAngle > 0 && o.foldAngle <= 90))
    throw Error(ErrorKind::BadParameter, "the fold angle must be in (0, 90] degrees");
  Model model = readModel(o.model);
  if (o.size > 0) model = scaledToSize(model, o.size);
  ArrangementParams& p = o.params.arrangement;
  p.u = o.uDirection();
  p.v = o.vDirection();
  p.stabilize.scheme = o.scheme == "u"   ? Scheme::DominantU
                       : o.scheme == "v" ? Scheme::DominantV
                                         : Scheme::Both;
  o.params.slots.end = o.slotEnd == "round" ? SlotEnd::Round : SlotEnd::Square;
  o.params.slots.uUp = o.uSlots == "up";
  const bool tty = ::isatty(2);
  const Design d = runDesign(model, o.params, [tty](const char* stage) {
    if (tty) std::fprintf(stderr, "\r\033[K%s ...", stage);
  });
  if (tty) std::fprintf(stderr, "\r\033[K");
  const Arrangement& a = d.arrangement;

  int nu = 0, nv = 0, holding = 0;
  for (const ScaffoldPatch& sp : a.scaffold.patches) (sp.family == Family::U ? nu : nv)++;
  for (const ScaffoldHinge& h : a.scaffold.hinges) holding += h.holds ? 1 : 0;
  const Vec3 size = model.bounds.size();
  std::printf("model      %s (%.1f x %.1f x %.1f mm, %zu triangles)\n", model.source.c_str(), size.x, size.y,
              size.z, model.mesh.triangles.size());
  std::printf("slices     %zu U, %zu V at %.3f / %.3f mm\n", a.u.slices.size(), a.v.slices.size(),
              a.u.interval, a.v.interval);
  std::printf("reeb       %zu U edges, %zu V edges\n", a.reebU.edges.size(), a.reebV.edges.size());
  std::printf("cylinders  %zu U, %zu V (%zu U and %zu V left without a patch)\n", a.uCylinders.size(),
              a.vCylinders.size(), a.scaffold.uncoveredU.size(), a.scaffold.uncoveredV.size());
  std::printf("patches    %d U, %d V\n", nu, nv);
  std::printf("hinges     %zu (%d holding)\n", a.scaffold.hinges.size(), holding);
  std::printf("stable     %s (nullity %d%s%s)\n", a.certificate.stable ? "yes" : "NO", a.certificate.nullity,
              a.certificate.reason.empty() ? "" : ": ", a.certificate.reason.c_str());
  std::printf("quality    silhouette IoU U %.3f, V %.3f, W %.3f; volume IoU %.3f\n", a.quality.silhouetteIouU,
              a.quality.silhouetteIouV, a.quality.silhouetteIouW, a.quality.volumeIou);
  printRealization(d, o.params);
  std::printf("time      ");
  double total = 0;
  for (const StageTime& t : d.timings) {
    std::printf(" %s %.1f ms,", t.stage.c_str(), t.ms);
    total += t.ms;
  }
  std::printf(" total %.1f ms\n", total);
  // A large cylinder left without a patch is usually a separate part of the model (a stand
  // under a ball) that no hinge connects to the rest: the scaffold is stable, but the part
  // is missing from it. Say so rather than let "stable" hide it.
  for (Family f : {Family::U, Family::V}) {
    const auto& cylinders = f == Family::U ? a.uCylinders : a.vCylinders;
    double largest = 0;
    for (const Cylinder& c : cylinders) largest = std::max(largest, c.section.area());
    int big = 0;
    for (int c : f == Family::U ? a.scaffold.uncoveredU : a.scaffold.uncoveredV)
      big += cylinders[c].section.area() >= 0.15 * largest ? 1 : 0;
    if (big > 0)
      std::printf(
          "warning    %d large %s cylinder(s) have no patch: a part of the model is not connected to the "
          "scaffold by hinges that hold\n",
          big, f == Family::U ? "U" : "V");
  }
  if (!o.output.empty()) writeOutputs(model, o.params, d, o);
  // Never hand on a design that cannot be built silently: the files are written so the
  // problem can be looked at, and the exit code says it failed.
  if (!a.certificate.stable)
    throw Error(ErrorKind::Geometry, "the scaffold is not stable: " + a.certificate.reason);
  if (!d.certificate.stable)
    throw Error(ErrorKind::Geometry, "the slotted design is not stable: " + d.certificate.reason);
  if (d.emitted.interlocks > 0 || d.emitted.splitPatches > 0)
    throw Error(ErrorKind::Geometry,
                "the design cannot be assembled: " + std::to_string(d.emitted.interlocks) +
                    " interlocked loop pair(s), " + std::to_string(d.emitted.splitPatches) +
                    " patch(es) in pieces");
}

}  // namespace

Run addDesignCommand(CLI::App& app) {
  auto o = std::make_shared<DesignOptions>();
  CLI::App* cmd =
      app.add_subcommand("design",
                         "Design a sliceform for the model: stable, slotted so it can be assembled, "
                         "with exact patches; summarise it and write it to a folder.");
  addModelOptions(cmd, *o);
  cmd->add_option("-o,--output", o->output,
                  "folder to write report.json, timings.json, assembly.step and assembly.brep into "
                  "(created if missing; files are replaced whole)");
  cmd->add_option(
         "--size", o->size,
         "scale the model so its longest side is this many mm (0: keep its size; mesh files carry no unit)")
      ->capture_default_str();
  cmd->add_option("-n,--slices", o->params.arrangement.slices, "slices per direction")->capture_default_str();
  cmd->add_option("--interval", o->params.arrangement.interval, "slice interval in mm (overrides --slices)");
  cmd->add_option("--tau-a", o->params.arrangement.tauA,
                  "cylinder error budget, relative to each part's volume")
      ->capture_default_str();
  cmd->add_option("--tau-m", o->params.arrangement.tauM, "Reeb branch merge threshold (weight ratio)")
      ->capture_default_str();
  cmd->add_option("--scheme", o->scheme, "both, or u / v for one dominant direction")
      ->check(CLI::IsMember({"both", "u", "v"}))
      ->capture_default_str();
  cmd->add_option("--min-hinge-length", o->params.arrangement.hinges.minHingeLength,
                  "mm a hinge must be long to carry load")
      ->capture_default_str();
  cmd->add_option("--min-slot-edge-distance", o->params.arrangement.hinges.minSlotEdgeDistance,
                  "mm of paper to keep on each side of a slot")
      ->capture_default_str();
  cmd->add_option("--thickness", o->params.slots.thickness, "mm of material (0.3 for card, 3 for plywood)")
      ->capture_default_str();
  cmd->add_option("--clearance", o->params.slots.clearance, "mm added to the thickness for the slot width")
      ->capture_default_str();
  cmd->add_option("--kerf", o->params.slots.kerf, "mm the cutter removes; cut paths are moved out by half")
      ->capture_default_str();
  cmd->add_option("--slot-end", o->slotEnd, "square, or round closed slot ends")
      ->check(CLI::IsMember({"square", "round"}))
      ->capture_default_str();
  cmd->add_option("--u-slots", o->uSlots,
                  "up or down: which way U-patches are slotted first (V the other way)")
      ->check(CLI::IsMember({"up", "down"}))
      ->capture_default_str();
  cmd->add_option("--fold-angle", o->foldAngle,
                  "degrees between the families in the 3D assembly: 90 is "
                  "popped up, small angles fold it flat")
      ->capture_default_str();
  cmd->add_option("--max-spacing", o->params.arrangement.stabilize.maxSpacing,
                  "mm; add patches in long cylinders so none is farther apart (0: off)")
      ->capture_default_str();
  return [o] { runDesign(*o); };
}

}  // namespace sliceform::cli
