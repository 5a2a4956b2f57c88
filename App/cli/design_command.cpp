// SPDX-License-Identifier: LGPL-2.1-or-later
// `sliceform design MODEL`: arranges a stable sliceform scaffold (§4) and prints a
// summary: patches per family, hinges, the certificate, quality, time per stage.
// --json writes the scaffold.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "arrangement/arrange.hpp"
#include "cli/commands.hpp"
#include "output/scaffold_json.hpp"
#include "support/error.hpp"

namespace sliceform::cli {
namespace {

struct DesignOptions : ModelOptions {
  std::string json;
  double size = 150;
  std::string scheme = "both";
  ArrangementParams params;
};

void runDesign(DesignOptions o) {
  Model model = readModel(o.model);
  if (o.size > 0) model = scaledToSize(model, o.size);
  ArrangementParams& p = o.params;
  p.u = o.uDirection();
  p.v = o.vDirection();
  p.stabilize.scheme = o.scheme == "u"   ? Scheme::DominantU
                       : o.scheme == "v" ? Scheme::DominantV
                                         : Scheme::Both;
  const Arrangement a = arrange(model, p);

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
  std::printf("time      ");
  double total = 0;
  for (const StageTime& t : a.timings) {
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
  if (!o.json.empty()) {
    writeJson(scaffoldJson(a, p), o.json);
    std::printf("wrote      %s\n", o.json.c_str());
  }
  // Never hand on an unstable scaffold silently: it is a bug in the frame logic.
  if (!a.certificate.stable)
    throw Error(ErrorKind::Geometry, "the scaffold is not stable: " + a.certificate.reason);
}

}  // namespace

Run addDesignCommand(CLI::App& app) {
  auto o = std::make_shared<DesignOptions>();
  CLI::App* cmd =
      app.add_subcommand("design", "Arrange a stable sliceform scaffold for the model and summarise it.");
  addModelOptions(cmd, *o);
  cmd->add_option("--json", o->json,
                  "write the scaffold (patches, hinges, certificate, quality) to this file");
  cmd->add_option(
         "--size", o->size,
         "scale the model so its longest side is this many mm (0: keep its size; mesh files carry no unit)")
      ->capture_default_str();
  cmd->add_option("-n,--slices", o->params.slices, "slices per direction")->capture_default_str();
  cmd->add_option("--interval", o->params.interval, "slice interval in mm (overrides --slices)");
  cmd->add_option("--tau-a", o->params.tauA, "cylinder error budget, relative to each part's volume")
      ->capture_default_str();
  cmd->add_option("--tau-m", o->params.tauM, "Reeb branch merge threshold (weight ratio)")
      ->capture_default_str();
  cmd->add_option("--scheme", o->scheme, "both, or u / v for one dominant direction")
      ->check(CLI::IsMember({"both", "u", "v"}))
      ->capture_default_str();
  cmd->add_option("--min-hinge-length", o->params.hinges.minHingeLength,
                  "mm a hinge must be long to carry load")
      ->capture_default_str();
  cmd->add_option("--min-slot-edge-distance", o->params.hinges.minSlotEdgeDistance,
                  "mm of paper to keep on each side of a slot")
      ->capture_default_str();
  cmd->add_option("--max-spacing", o->params.stabilize.maxSpacing,
                  "mm; add patches in long cylinders so none is farther apart (0: off)")
      ->capture_default_str();
  return [o] { runDesign(*o); };
}

}  // namespace sliceform::cli
