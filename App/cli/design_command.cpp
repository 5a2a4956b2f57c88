// SPDX-License-Identifier: LGPL-2.1-or-later
// `sliceform design MODEL -o DIR`: arranges a stable sliceform scaffold (§4), slots it so
// it can be assembled (§5), builds the exact patches, lays them out on sheets and prints a
// summary: patches, hinges, the certificate, interlocks, slots, quality, sheets, time per
// stage. With -o it writes everything a maker needs into DIR (see kOutputs).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <filesystem>

#include <unistd.h>

#include "cli/commands.hpp"
#include "output/coupon.hpp"
#include "output/design_files.hpp"
#include "pipeline/design.hpp"
#include "pipeline/directions.hpp"
#include "support/error.hpp"
#include "support/stopwatch.hpp"

namespace sliceform::cli {
namespace {

constexpr const char* kManual = R"(What it does:
  Slices the model into two families of parallel patches (U and V), keeps a set that holds
  together (the rigidity certificate), cuts a slot at every joint so the patches slide
  together without locking into each other, lays them out on sheets with labels, and
  writes the files below. The summary on stdout says what was found; the exit code says
  whether the design can be built.

Files written into the -o folder:
  sheets.pdf        every sheet, one page each, at 1:1: print at 100 % (actual size) and
                    check the 50 mm bar in the bottom margin
  sheet-N.svg       sheet N for laser cutters and vinyl plotters, in mm: red = cut,
                    blue = engrave (the patch id, and beside each slot the partner's id)
  sheet-N.dxf       the same in DXF (layers CUT and ENGRAVE, mm, arcs as arcs)
  sheets.png        a preview of all sheets
  assembly.png      a picture of the assembled sliceform
  assembly.step     the assembled sliceform at --fold-angle, for CAD; assembly.brep the same
  assembly.glb      the same for viewers (glTF, metres)
  report.json       the design, documented in docs/report-format.md; same input, same bytes
  timings.json      time per stage

Assembling: put the patches together in report.json's assembly_order, each slot onto the
partner whose id is engraved beside it.

Exit codes:
  0  the design is written and can be built
  1  the design cannot be built (not stable, loops interlock, a patch falls apart: the
     files are still written so it can be looked at), or an internal error
  2  wrong command line
  3  the model cannot be used (unreadable, not a closed solid, ...)
  4  a parameter is out of range (also: a patch larger than the sheet)
  5  an output cannot be written)";

struct DesignOptions : ModelOptions {
  std::string output;
  double size = parameterSpec("size").value;
  double height = parameterSpec("height").value;
  std::string sheet = parameterSpec("sheet").choices.front();
  double margin = parameterSpec("margin").value, spacing = parameterSpec("spacing").value;
  bool noRotate = parameterSpec("rotate").value == 0;
  std::string scheme = parameterSpec("scheme").choices.front();
  std::string directions = parameterSpec("directions").choices.front();
  bool frameChosen = false;  // --u, --v or --directions on the command line
  bool coupon = false;
  std::string slotEnd = parameterSpec("slot_end").choices.front();
  std::string uSlots = parameterSpec("u_slots").choices.front();
  double foldAngle = parameterSpec("fold_angle").value;
  DesignParams params;
};

void printRealization(const Design& d, const DesignParams& params) {
  const Realization& r = d.realization;
  std::printf(
      "grazes     %d hinge(s) no slot could cut without splitting a patch; %d patch(es) moved by a slice "
      "or two, %d taken out; %d left\n",
      d.grazes.found, d.grazes.moved, d.grazes.dropped, d.grazes.remaining);
  if (d.grazes.splitMoved + d.grazes.splitDropped > 0)
    std::printf("resplit    %d patch(es) the slot search left split moved, %d taken out\n",
                d.grazes.splitMoved, d.grazes.splitDropped);
  std::printf("interlocks %d found, %d repaired, %d remaining; %d cut-through(s); %d split patch(es)\n",
              r.interlocks.found, r.interlocks.repaired, d.emitted.interlocks, r.interlocks.cutThroughs,
              d.emitted.splitPatches);
  std::printf("slotted    stable %s (nullity %d); %d pair(s) lost every holding hinge\n",
              d.certificate.stable ? "yes" : "NO", d.certificate.nullity, r.lostPins);
  std::printf("slots      %.2f mm wide; smallest slot-to-edge distance %.2f mm; shortest hinge %.2f mm\n",
              params.slots.width(), r.minSlotEdgeDistance, r.shortestHinge);
  if (d.emitted.closest.first >= 0)
    std::printf(
        "spacing    closest stacked patches %.2f mm apart (%s, %s), %.2f mm of paper between their "
        "slots (rule: %.2f mm apart)\n",
        d.emitted.minPatchSpacing, patchId(d.arrangement.scaffold, d.emitted.closest.first).c_str(),
        patchId(d.arrangement.scaffold, d.emitted.closest.second).c_str(),
        d.emitted.minPatchSpacing - params.slots.width(), d.arrangement.minSpacing);
  std::printf("collisions %zu U/V pair(s) overlapping along their common line\n",
              d.emitted.collisions.size());
  int exact = 0;
  for (const PatchFace& p : d.patches) exact += p.exact ? 1 : 0;
  std::printf("exact      %d of %zu patches from the BRep's exact sections, the others polygons", exact,
              d.patches.size());
  if (d.exactReplaced > 0)
    std::printf(" (%d exact face(s) broke a rule their polygon keeps and were replaced)", d.exactReplaced);
  std::printf("\n");
  std::printf("assembly   %s:",
              r.assemblyChecked ? "order checked pairwise" : "ORDER NOT FREE of interlocks");
  for (const int k : r.assemblyOrder) std::printf(" %s", patchId(d.arrangement.scaffold, k).c_str());
  std::printf("\n");
}

void writeOutputs(const Model& model, const DesignParams& params, const Design& d, const DesignOptions& o,
                  const std::vector<StageTime>& before, DesignFilesWriter& writer) {
  const DesignFiles files = writer.finish(model, params, d, before);
  for (const std::string& name : files.removed)
    std::printf("removed    %s/%s, left by an earlier run with more sheets\n", o.output.c_str(),
                name.c_str());
  const int sheets = d.layout.packing.sheets;
  const std::string sheetNames = sheets == 1 ? "sheet-1" : "sheet-1.." + std::to_string(sheets);
  std::printf(
      "wrote      %s: report.json, timings.json, sheets.pdf, sheets.png, %s.svg and .dxf; "
      "assembly.step, .brep, .glb and .png at %g degrees; instructions.pdf\n",
      o.output.c_str(), sheetNames.c_str(), o.foldAngle);
}

void printLayout(const SheetLayout& l) {
  int missing = 0, partners = 0, leaders = 0;
  std::string without;  // the patches with a slot left unlabelled
  for (const FlatPatch& p : l.patches) {
    missing += static_cast<int>(p.unlabelled.size()), partners += static_cast<int>(p.partners.size()),
        leaders += p.partnersOnLeaders;
    if (p.unlabelled.empty()) continue;
    std::string slots;  // "V5 (slot for U11)"
    for (const UnlabelledSlot& slot : p.unlabelled) slots += (slots.empty() ? "" : ", ") + slot.partner;
    without += (without.empty() ? "" : "; ") + p.id + " (slot for " + slots + ")";
  }
  std::printf("sheets     %d %s (%.0f x %.0f mm), %.0f %% used; shelf layout would take %d (%.0f %%)\n",
              l.packing.sheets, l.sheet.name.c_str(), l.sheet.width, l.sheet.height,
              100 * l.packing.utilisation, l.shelf.sheets, 100 * l.shelf.utilisation);
  std::printf("labels     %zu patch ids, %d partner ids at slots", l.patches.size(), partners);
  if (leaders > 0) std::printf(" (%d with a leader line to a slot too crowded for it)", leaders);
  int steps = 0;
  for (const FlatPatch& p : l.patches) steps += p.step > 0 && p.stepLabel.height <= 0;
  std::printf("; partner_labels_missing %d", missing);
  if (missing > 0) std::printf(" (no room to read as the slot's on %s)", without.c_str());
  if (steps > 0) std::printf("; %d patch(es) with no room for their step number", steps);
  std::printf("\n");
}

// A bar on stderr while the stages run, when stderr is a terminal.
class ProgressBar {
 public:
  explicit ProgressBar(bool show) : show_(show), start_(std::chrono::steady_clock::now()) {}
  void operator()(const char* stage) {
    if (!show_) return;
    if (stage_ == kDesignStages) stage_ = 0;  // the next frame's design (--directions auto)
    const int width = 24, done = width * stage_++ / kDesignStages;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::fprintf(stderr, "\r\033[K[%s%s] %d/%d %s (%.0f s)", std::string(done, '#').c_str(),
                 std::string(width - done, '.').c_str(), stage_, kDesignStages, stage, seconds);
  }
  void clear() const {
    if (show_) std::fprintf(stderr, "\r\033[K");
  }

 private:
  bool show_;
  int stage_ = 0;
  std::chrono::steady_clock::time_point start_;
};

// The model at the asked size: longest side, or height along W (u x v), in mm.
Model sized(Model model, const DesignOptions& o) {
  // 0 keeps the size; anything else must be a length (scaledTo* refuse negatives and NaN).
  if (o.height != 0) return scaledToHeight(model, cross(o.uDirection(), o.vDirection()), o.height);
  return o.size != 0 ? scaledToSize(model, o.size) : model;
}

void runDesign(DesignOptions o) {
  if (!(o.foldAngle > 0 && o.foldAngle <= 90))
    throw Error(ErrorKind::BadParameter, "the fold angle must be in (0, 90] degrees");
  if (o.directions == "auto" && o.height != 0)
    throw Error(ErrorKind::BadParameter,
                "--height measures along W, which --directions auto chooses: give --size instead");
  std::vector<StageTime> readTime;
  Stopwatch clock(readTime);
  const Model model = sized(readModel(o.model, o.fillHoles), o);
  clock.lap("read");
  ArrangementParams& p = o.params.arrangement;
  p.u = o.uDirection();
  p.v = o.vDirection();
  p.stabilize.scheme = o.scheme == "u"   ? Scheme::DominantU
                       : o.scheme == "v" ? Scheme::DominantV
                                         : Scheme::Both;
  o.params.slots.end = o.slotEnd == "round" ? SlotEnd::Round : SlotEnd::Square;
  o.params.slots.uUp = o.uSlots == "up";
  o.params.sheet = sheetSpec(o.sheet, o.margin, o.spacing);
  o.params.sheet.rotate = !o.noRotate;
  ProgressBar bar(::isatty(2));
  // The 3D assembly's STEP file is started as soon as the patches are final.
  std::optional<DesignFilesWriter> writer;
  if (!o.output.empty()) writer.emplace(o.output, o.foldAngle);
  const auto ready = [&](const Design& partial) {
    if (writer) writer->start(partial);
  };
  DirectionChoice choice;
  // --height measures along the file's W: its frame is then chosen too.
  const bool mayTurn = !o.frameChosen && o.height == 0;
  std::optional<Design> given;
  std::string refusal;  // why the file's axes give no buildable design
  const auto begun = std::chrono::steady_clock::now();
  const Deadline deadline(o.params.timeLimit);  // the whole run's, other frames included
  // The file's axes: laid out, and their 3D files begun, only once they are what is kept.
  // Buildability reads nothing of the layout, so a design that will give way to other frames
  // costs neither (occ/Top.brep: a 0.9 s layout and a 2.3 s STEP file, both thrown away).
  bool laidOut = false;
  const auto layOutGiven = [&] {
    if (laidOut) return;
    ready(*given);
    layOutDesign(*given, o.params.sheet, std::ref(bar));
    laidOut = true;
  };
  if (o.directions == "auto") {
    given = designInBestFrame(model, o.params, choice, std::ref(bar), ready, &deadline);
    laidOut = true;
  } else {
    try {
      // Where other frames follow, a design with many patches in pieces is not repaired:
      // those frames are tried first (occ/Top.brep: 11 in pieces, 24 repair searches).
      given = designPatches(model, o.params, std::ref(bar), &deadline, nullptr,
                            mayTurn ? SplitRepair::WhenFew : SplitRepair::Always);
      const std::vector<std::string> problems = designProblems(*given);
      if (!problems.empty()) refusal = problems.front();
      if (refusal.empty() || !mayTurn) layOutGiven();
    } catch (const Error& e) {
      if (e.kind() != ErrorKind::Unbuildable || !mayTurn) throw;
      refusal = e.what();
    }
  }
  // The file's axes are no one's choice when none was given: where they give no design a
  // maker can build, other directions may (TR12J_OCC.stl: a patch in pieces at the file's
  // axes, buildable turned). The design in the best frame is kept only if it can be built.
  const double firstMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begun).count();
  if (!refusal.empty() && mayTurn && deadline.passed()) {
    bar.clear();
    std::printf(
        "directions the file's axes give no buildable design (%s); the time limit (%g s) left "
        "no time to try others\n",
        refusal.c_str(), o.params.timeLimit);
    if (!given) throw Error(ErrorKind::Unbuildable, refusal);
    layOutGiven();
  } else if (!refusal.empty() && mayTurn) {
    bar.clear();
    std::printf(
        "directions the file's axes give no buildable design (%s); trying others (--directions auto)\n",
        refusal.c_str());
    std::fflush(stdout);
    // A no-op today (the file's axes begin nothing when other frames follow): a STEP file
    // begun for them must never stand for another frame's design.
    if (writer) writer->discard();
    DirectionChoice other;
    std::optional<Design> turned;
    try {
      turned = designInBestFrame(model, o.params, other, std::ref(bar), ready, &deadline, nullptr,
                                 given ? &*given : nullptr);
    } catch (const Error& e) {
      if (e.kind() != ErrorKind::Unbuildable && e.kind() != ErrorKind::BadInput) throw;
    }
    if (turned && designProblems(*turned).empty()) {
      turned->timings.insert(turned->timings.begin(),
                             {"directions (the file's axes, not buildable)", firstMs});
      given = std::move(turned);
      choice = std::move(other);
      choice.why = "the file's axes gave no buildable design; " + choice.why;
      given->directions.why = choice.why;  // report.json's copy
    } else {
      bar.clear();
      std::printf("directions no other frame tried gives a buildable design either: the file's axes kept\n");
      if (!given) throw Error(ErrorKind::Unbuildable, refusal);
      if (writer) writer->discard();  // the other frame's, begun when it was laid out
      if (given->grazes.splitLeft) {
        // Kept after all: repaired now, as far as the repair goes (its first stages taken).
        Design repaired = designPatches(model, o.params, std::ref(bar), &deadline, &*given);
        given = std::move(repaired);
      }
      layOutGiven();
    }
  }
  const Design& d = *given;
  if (choice.automatic) {
    // From here on, as if they had been given: report.json's parameters carry them.
    p.u = choice.trials[choice.chosen].u;
    p.v = choice.trials[choice.chosen].v;
  }
  bar.clear();
  const Arrangement& a = d.arrangement;

  int nu = 0, nv = 0, holding = 0;
  for (const ScaffoldPatch& sp : a.scaffold.patches) (sp.family == Family::U ? nu : nv)++;
  for (const ScaffoldHinge& h : a.scaffold.hinges) holding += h.holds ? 1 : 0;
  const Vec3 size = model.bounds.size();
  std::printf("model      %s (%.1f x %.1f x %.1f mm, %zu triangles)\n", model.source.c_str(), size.x, size.y,
              size.z, model.mesh.triangles.size());
  if (model.holesFilled > 0)
    std::printf("repaired   %zu %shole(s) of the mesh filled (fans about their centres)\n", model.holesFilled,
                o.fillHoles ? "" : "small ");
  if (model.edgesSplit > 0)
    std::printf("repaired   %zu edge(s) where closed parts of the mesh touch split apart\n",
                model.edgesSplit);
  if (choice.automatic)
    std::printf("directions auto: %s; U %.3f,%.3f,%.3f, V %.3f,%.3f,%.3f\n", choice.why.c_str(), p.u.x, p.u.y,
                p.u.z, p.v.x, p.v.y, p.v.z);
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
  printLayout(d.layout);
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
  if (!o.output.empty()) writeOutputs(model, o.params, d, o, readTime, *writer);
  if (o.coupon && !o.output.empty()) {
    writeCoupon(makeCoupon(o.params.slots, p.hinges.minSlotEdgeDistance, a.minSpacing), o.output);
    std::printf(
        "coupon     %s: coupon.pdf, .svg, .dxf, .png, .json (sliceform coupon --help says how to use it)\n",
        o.output.c_str());
  }
  // Never hand on a design that cannot be built silently: the files are written so the
  // problem can be looked at, and the exit code says it failed.
  const std::vector<std::string> problems = designProblems(d);
  if (!problems.empty()) {
    std::string all;
    for (const std::string& p : problems) all += (all.empty() ? "" : "; ") + p;
    throw Error(ErrorKind::Geometry, "the design cannot be built: " + all);
  }
}

}  // namespace

Run addDesignCommand(CLI::App& app) {
  auto o = std::make_shared<DesignOptions>();
  CLI::App* cmd =
      app.add_subcommand("design",
                         "Design a sliceform for the model: stable, slotted so it can be assembled, "
                         "with exact patches; summarise it and write it to a folder.");
  addModelOptions(cmd, *o);
  cmd->footer(kManual);
  cmd->add_option("-o,--output", o->output,
                  "folder to write the sheets, the 3D assembly and report.json into (created if missing; "
                  "files are replaced whole)");
  CLI::Option* size = addParameter(cmd, "size", o->size);
  addParameter(cmd, "height", o->height)->excludes(size);
  addParameter(cmd, "sheet", o->sheet)->group("Sheets");
  addParameter(cmd, "margin", o->margin)->group("Sheets");
  addParameter(cmd, "spacing", o->spacing)->group("Sheets");
  cmd->add_flag(parameterSpec("rotate").option, o->noRotate, parameterSpec("rotate").help)->group("Sheets");
  addParameter(cmd, "slices", o->params.arrangement.slices, "-n,--slices");
  addParameter(cmd, "interval", o->params.arrangement.interval);
  addParameter(cmd, "tau_a", o->params.arrangement.tauA);
  addParameter(cmd, "tau_m", o->params.arrangement.tauM);
  addParameter(cmd, "directions", o->directions)
      ->description(parameterSpec("directions").help +
                    "; report.json lists the frames. With none of --u, --v, --directions, --height: the "
                    "file's axes, and auto when they give no buildable design")
      ->excludes(cmd->get_option("--u"))
      ->excludes(cmd->get_option("--v"));
  addParameter(cmd, "scheme", o->scheme);
  addParameter(cmd, "min_hinge_length", o->params.arrangement.hinges.minHingeLength);
  addSlotOptions(cmd, o->params.slots, o->params.arrangement.hinges, o->params.arrangement.stabilize);
  cmd->add_flag("--coupon", o->coupon,
                "also write the fit test coupon (sliceform coupon) into the output folder");
  addParameter(cmd, "slot_end", o->slotEnd);
  addParameter(cmd, "u_slots", o->uSlots);
  addParameter(cmd, "fold_angle", o->foldAngle);
  addParameter(cmd, "max_spacing", o->params.arrangement.stabilize.maxSpacing);
  addParameter(cmd, "time_limit", o->params.timeLimit);
  return [o, cmd] {
    o->frameChosen = cmd->count("--u") + cmd->count("--v") + cmd->count("--directions") > 0;
    runDesign(*o);
  };
}

}  // namespace sliceform::cli
