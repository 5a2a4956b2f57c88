// SPDX-License-Identifier: LGPL-2.1-or-later
#include "output/report_json.hpp"

#include <fstream>
#include <stdexcept>

#include "support/atomic_file.hpp"
#include "support/error.hpp"
#include "support/per_family.hpp"

namespace sliceform {
namespace {

using nlohmann::json;

json vec(const Vec3& v) {
  return json::array({v.x, v.y, v.z});
}

const char* schemeName(Scheme s) {
  switch (s) {
    case Scheme::DominantU:
      return "U";
    case Scheme::DominantV:
      return "V";
    case Scheme::Both:
      return "both";
  }
  return "both";
}

// Outer loop first, then the holes (Region2d gives them in Clipper's order).
json outline(const Region2d& region) {
  std::vector<Region2d::Loop> loops = region.loops();
  std::stable_partition(loops.begin(), loops.end(),
                        [](const Region2d::Loop& l) { return Region2d::signedArea(l) > 0; });
  json out = json::array();
  for (const Region2d::Loop& loop : loops) {
    json points = json::array();
    for (const Vec2& q : loop) points.push_back({q.x, q.y});
    out.push_back(points);
  }
  return out;
}

json label(const Label& l) {
  return {{"text", l.text}, {"at", {l.at.x, l.at.y}}, {"height_mm", l.height}, {"vertical", l.vertical}};
}

json qualityJson(const Quality& q) {
  return {{"silhouette_iou_u", q.silhouetteIouU},
          {"silhouette_iou_v", q.silhouetteIouV},
          {"silhouette_iou_w", q.silhouetteIouW},
          {"volume_iou", q.volumeIou}};
}

// Every frame tried for `--directions auto`, its estimate and, for the few designed, the
// design; `chosen` indexes `frames`.
json directionsJson(const DirectionChoice& c) {
  json frames = json::array();
  for (const FrameTrial& t : c.trials) {
    json f = {{"name", t.name},
              {"u", vec(t.u)},
              {"v", vec(t.v)},
              {"stands", t.stands},
              {"estimate", {{"quality", qualityJson(t.estimate)}, {"patches", t.estimatePatches}}},
              {"score", t.score},
              {"designed", t.designed}};
    if (!t.failure.empty()) f["failure"] = t.failure;
    if (t.designed) {
      f["design"] = {{"buildable", t.buildable},
                     {"quality", qualityJson(t.quality)},
                     {"patches", t.patches},
                     {"score", t.designScore}};
      if (t.laidOut) f["design"]["sheets"] = t.sheets;  // not laid out once it could not win
    }
    frames.push_back(f);
  }
  return {{"mode", "auto"}, {"frames", frames}, {"chosen", c.chosen}, {"why", c.why}};
}

}  // namespace

json reportJson(const Model& model, const DesignParams& params, const Design& d) {
  const Arrangement& a = d.arrangement;
  // Every patch's sheet is reported: a design from designPatches alone has none yet.
  if (d.layout.patches.size() != a.scaffold.patches.size() ||
      d.layout.packing.placements.size() != a.scaffold.patches.size())
    throw std::invalid_argument("reportJson: the design is not laid out (layOutDesign)");
  const Realization& r = d.realization;
  const ArrangementParams& p = params.arrangement;
  json doc;
  doc["format"] = "sliceform-report";
  doc["version"] = 1;
  doc["parameters"] = {{"u", vec(p.u)},
                       {"v", vec(p.v)},
                       {"slices", p.slices},
                       {"interval_mm", a.u.interval},
                       {"tau_a", p.tauA},
                       {"tau_m", p.tauM},
                       {"scheme", schemeName(p.stabilize.scheme)},
                       {"max_spacing_mm", p.stabilize.maxSpacing},
                       {"min_spacing_mm", a.minSpacing},
                       {"min_hinge_length_mm", p.hinges.minHingeLength},
                       {"min_slot_edge_distance_mm", p.hinges.minSlotEdgeDistance},
                       {"thickness_mm", params.slots.thickness},
                       {"clearance_mm", params.slots.clearance},
                       {"slot_width_mm", params.slots.width()},
                       {"kerf_mm", params.slots.kerf},
                       {"slot_end", params.slots.end == SlotEnd::Round ? "round" : "square"},
                       {"u_slots", params.slots.uUp ? "up" : "down"}};
  const Vec3 lo = model.bounds.min, hi = model.bounds.max;
  doc["model"] = {{"source", model.source},
                  {"kind", model.kind == SourceKind::Brep ? "brep" : "mesh"},
                  {"triangles", model.mesh.triangles.size()},
                  {"holes_filled", model.holesFilled},
                  {"edges_split", model.edgesSplit},
                  {"bbox_mm", {vec(lo), vec(hi)}}};
  if (model.everyHoleFilled) doc["model"]["every_hole_filled"] = true;  // --fill-holes; absent if not
  json patches = json::array();
  for (int k = 0; k < static_cast<int>(a.scaffold.patches.size()); ++k) {
    const ScaffoldPatch& sp = a.scaffold.patches[k];
    const PatchPlane plane = patchPlane(a, k);
    const PatchFace& face = d.patches[k];
    const FlatPatch& flat = d.layout.patches[k];
    const Placement& at = d.layout.packing.placements[k];
    json missingFor = json::array();
    for (const UnlabelledSlot& slot : flat.unlabelled) missingFor.push_back(slot.partner);
    patches.push_back(
        {{"id", patchId(a.scaffold, k)},
         {"family", familyName(sp.family)},
         {"cylinder", sp.cylinder},
         {"slice", sp.slice},
         {"origin", vec(plane.origin)},
         {"normal", vec(plane.normal)},
         {"x_axis", vec(plane.xAxis)},
         {"y_axis", vec(plane.yAxis)},
         {"area_mm2", face.outline.area()},
         {"exact", face.exact},
         {"outline", outline(face.outline)},
         {"sheet", at.sheet + 1},
         {"placement", {{"x_mm", at.offset.x}, {"y_mm", at.offset.y}, {"rotation_deg", at.rotation}}},
         {"label", label(flat.name)},
         {"step", flat.step},
         {"step_label", label(flat.stepLabel)},
         {"partner_labels", flat.partners.size()},
         {"partner_labels_missing", flat.unlabelled.size()},
         {"partner_labels_missing_for", missingFor},
         {"partner_labels_on_leaders", flat.partnersOnLeaders}});
  }
  doc["patches"] = patches;
  json hinges = json::array();
  int collapsed = 0;
  for (size_t h = 0; h < a.scaffold.hinges.size(); ++h) {
    const ScaffoldHinge& hinge = a.scaffold.hinges[h];
    // A hinge whose slotted patches no longer meet along it is not a hinge of the design.
    if (!d.emitted.meets[h]) {
      ++collapsed;
      continue;
    }
    const auto [p0, p1] = hingeEnds(a, hinge);
    hinges.push_back({{"a", patchId(a.scaffold, hinge.u)},
                      {"b", patchId(a.scaffold, hinge.v)},
                      {"p0", vec(p0)},
                      {"p1", vec(p1)},
                      {"holds", hinge.holds},
                      {"slot_a", slotName(uSlot(r.slots[h]))},
                      {"slot_b", slotName(vSlot(r.slots[h]))}});
  }
  doc["hinges"] = hinges;
  doc["hinges_cleared_by_slots"] = collapsed;
  doc["certificate"] = {{"stable", d.certificate.stable},
                        {"nullity", d.certificate.nullity},
                        {"pins", d.certificate.pins},
                        {"reason", d.certificate.reason}};
  doc["interlocks"] = {{"found", r.interlocks.found},
                       {"repaired", r.interlocks.repaired},
                       {"remaining", d.emitted.interlocks},
                       {"cut_throughs", r.interlocks.cutThroughs}};
  doc["split_patches"] = d.emitted.splitPatches;
  doc["collisions"] = d.emitted.collisions.size();
  const bool stacked = d.emitted.closest.first >= 0;
  doc["min_patch_spacing_mm"] = stacked ? json(d.emitted.minPatchSpacing) : json(nullptr);
  doc["min_finger_mm"] = stacked ? json(d.emitted.minPatchSpacing - params.slots.width()) : json(nullptr);
  doc["exact_replaced_by_polygons"] = d.exactReplaced;
  json problems = json::array();
  for (const std::string& p : designProblems(d)) problems.push_back(p);
  doc["verdict"] = {{"buildable", problems.empty()}, {"problems", problems}};
  doc["min_slot_edge_distance_mm"] = r.minSlotEdgeDistance;
  doc["min_hinge_length_mm"] = r.shortestHinge;
  doc["quality"] = {{"silhouette_iou_u", a.quality.silhouetteIouU},
                    {"silhouette_iou_v", a.quality.silhouetteIouV},
                    {"silhouette_iou_w", a.quality.silhouetteIouW},
                    {"volume_iou", a.quality.volumeIou}};
  json order = json::array();
  for (const int k : r.assemblyOrder) order.push_back(patchId(a.scaffold, k));
  doc["assembly_order"] = order;
  doc["assembly_order_checked"] = r.assemblyChecked;
  const SheetLayout& l = d.layout;
  doc["sheets"] = {{"count", l.packing.sheets},
                   {"name", l.sheet.name},
                   {"size_mm", {l.sheet.width, l.sheet.height}},
                   {"margin_mm", l.sheet.margin},
                   {"spacing_mm", l.sheet.spacing},
                   {"rotations", l.sheet.rotate},
                   {"utilisation", l.packing.utilisation},
                   {"shelf_count", l.shelf.sheets},
                   {"shelf_utilisation", l.shelf.utilisation}};
  // Slots without their partner's id: what whoever assembles has to work out from the 3D.
  int partners = 0, missing = 0, leaders = 0;
  for (const FlatPatch& p : l.patches)
    partners += static_cast<int>(p.partners.size()), missing += static_cast<int>(p.unlabelled.size()),
        leaders += p.partnersOnLeaders;
  doc["partner_labels"] = partners;
  doc["partner_labels_missing"] = missing;
  doc["partner_labels_on_leaders"] = leaders;  // of partner_labels: they stand off, a line leads to the slot
  int steps = 0;
  for (const FlatPatch& p : l.patches) steps += p.step > 0 && p.stepLabel.height <= 0;
  doc["step_labels_missing"] = steps;  // patches with no room for their "#step" beside the id
  doc["cylinders"] = {{"u", a.uCylinders.size()},
                      {"v", a.vCylinders.size()},
                      {"uncovered_u", a.scaffold.uncoveredU},
                      {"uncovered_v", a.scaffold.uncoveredV}};
  if (d.directions.automatic) doc["directions"] = directionsJson(d.directions);
  return doc;
}

json timingsJson(const std::vector<StageTime>& timings) {
  json out = json::object();
  double total = 0;
  for (const StageTime& t : timings) {
    out[t.stage] = t.ms;
    if (!t.alongside) total += t.ms;
  }
  out["total"] = total;
  return out;
}

void writeJson(const json& doc, const std::string& path) {
  writeAtomically(path, [&](const std::string& temporary) {
    std::ofstream out(temporary);
    out << doc.dump(1) << "\n";
    if (!out.good()) throw Error(ErrorKind::Io, "cannot write " + path);
  });
}

}  // namespace sliceform
