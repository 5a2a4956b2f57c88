// SPDX-License-Identifier: LGPL-2.1-or-later
#include "output/scaffold_json.hpp"

#include <fstream>

#include "support/atomic_file.hpp"
#include "support/error.hpp"

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

}  // namespace

json scaffoldJson(const Arrangement& a, const ArrangementParams& p) {
  json doc;
  doc["parameters"] = {{"u", vec(p.u)},
                       {"v", vec(p.v)},
                       {"slices", p.slices},
                       {"interval_mm", a.u.interval},
                       {"tau_a", p.tauA},
                       {"tau_m", p.tauM},
                       {"scheme", schemeName(p.stabilize.scheme)},
                       {"max_spacing_mm", p.stabilize.maxSpacing}};
  doc["min_hinge_length_mm"] = p.hinges.minHingeLength;
  doc["min_slot_edge_distance_mm"] = p.hinges.minSlotEdgeDistance;
  json patches = json::array();
  for (int k = 0; k < static_cast<int>(a.scaffold.patches.size()); ++k) {
    const ScaffoldPatch& sp = a.scaffold.patches[k];
    const PatchPlane plane = patchPlane(a, k);
    const Cylinder& cyl = (sp.family == Family::U ? a.uCylinders : a.vCylinders)[sp.cylinder];
    json loops = json::array();
    for (const Region2d::Loop& loop : cyl.section.loops()) {
      json points = json::array();
      for (const Vec2& q : loop) points.push_back({q.x, q.y});
      loops.push_back(points);
    }
    patches.push_back({{"id", patchId(a.scaffold, k)},
                       {"family", sp.family == Family::U ? "U" : "V"},
                       {"cylinder", sp.cylinder},
                       {"slice", sp.slice},
                       {"origin", vec(plane.origin)},
                       {"normal", vec(plane.normal)},
                       {"x_axis", vec(plane.xAxis)},
                       {"y_axis", vec(plane.yAxis)},
                       {"area_mm2", cyl.section.area()},
                       {"outline", loops}});
  }
  doc["patches"] = patches;
  json hinges = json::array();
  for (const ScaffoldHinge& h : a.scaffold.hinges) {
    const auto [p0, p1] = hingeEnds(a, h);
    hinges.push_back({{"a", patchId(a.scaffold, h.u)},
                      {"b", patchId(a.scaffold, h.v)},
                      {"p0", vec(p0)},
                      {"p1", vec(p1)},
                      {"holds", h.holds}});
  }
  doc["hinges"] = hinges;
  doc["certificate"] = {{"stable", a.certificate.stable},
                        {"nullity", a.certificate.nullity},
                        {"pins", a.certificate.pins},
                        {"reason", a.certificate.reason}};
  doc["quality"] = {{"silhouette_iou_u", a.quality.silhouetteIouU},
                    {"silhouette_iou_v", a.quality.silhouetteIouV},
                    {"silhouette_iou_w", a.quality.silhouetteIouW},
                    {"volume_iou", a.quality.volumeIou}};
  doc["cylinders"] = {{"u", a.uCylinders.size()},
                      {"v", a.vCylinders.size()},
                      {"uncovered_u", a.scaffold.uncoveredU},
                      {"uncovered_v", a.scaffold.uncoveredV}};
  return doc;
}

void writeJson(const json& doc, const std::string& path) {
  writeAtomically(path, [&](const std::string& temporary) {
    std::ofstream out(temporary);
    out << doc.dump(1) << "\n";
    if (!out.good()) throw Error(ErrorKind::Io, "cannot write " + path);
  });
}

}  // namespace sliceform
