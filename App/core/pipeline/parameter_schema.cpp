// SPDX-License-Identifier: LGPL-2.1-or-later
#include "pipeline/parameter_schema.hpp"

#include <stdexcept>

#include "pipeline/design.hpp"

namespace sliceform {
namespace {

ParamSpec real(std::string key, std::string option, std::string property, std::string group, std::string unit,
               double value, double min, double max, double step, std::string label, std::string help) {
  ParamSpec s;
  s.key = std::move(key), s.option = std::move(option), s.property = std::move(property);
  s.group = std::move(group), s.kind = ParamKind::Real, s.unit = std::move(unit);
  s.value = value, s.min = min, s.max = max, s.step = step;
  s.label = std::move(label), s.help = std::move(help);
  return s;
}

// An on/off switch: default `on`.
ParamSpec flag(std::string key, std::string option, std::string property, std::string group, bool on,
               std::string label, std::string help) {
  ParamSpec s = real(std::move(key), std::move(option), std::move(property), std::move(group), "", on, 0, 1,
                     1, std::move(label), std::move(help));
  s.kind = ParamKind::Bool;
  return s;
}

ParamSpec choice(std::string key, std::string option, std::string property, std::string group,
                 std::vector<std::string> choices, std::string label, std::string help) {
  ParamSpec s;
  s.key = std::move(key), s.option = std::move(option), s.property = std::move(property);
  s.group = std::move(group), s.kind = ParamKind::Choice, s.choices = std::move(choices);
  s.label = std::move(label), s.help = std::move(help);
  return s;
}

ParamSpec direction(std::string key, std::string property, std::vector<double> value, std::string help) {
  ParamSpec s;
  s.key = key, s.option = "--" + key, s.property = std::move(property), s.group = "Slicing";
  s.kind = ParamKind::Direction, s.direction = std::move(value);
  s.label = s.property, s.help = std::move(help);
  return s;
}

std::vector<ParamSpec> make() {
  // Defaults the core's structs hold come from them; ranges are what the core accepts
  // (arrange.cpp, slots.cpp, nesting.cpp, fold.cpp and model.cpp refuse the rest).
  const DesignParams d{};
  const ArrangementParams& a = d.arrangement;
  std::vector<ParamSpec> out;
  out.push_back(
      choice("directions", "--directions", "Directions", "Slicing", {"given", "auto"}, "Directions",
             "given: slice along u and v; auto: try the model's principal axes and the file's axes, "
             "each up and the families turned about it, and keep the buildable frame that scores best "
             "(1.5-3 times the time of one design)"));
  out.push_back(
      direction("u", "UDirection", {a.u.x, a.u.y, a.u.z}, "normal of the U family of patches, x,y,z"));
  out.push_back(direction("v", "VDirection", {a.v.x, a.v.y, a.v.z},
                          "normal of the V family, x,y,z, orthogonal to U (W = U x V is up)"));
  out.push_back(
      flag("fill_holes", "--fill-holes", "FillHoles", "Slicing", false, "Fill every hole",
           "fill every hole of a mesh, not only those up to " +
               std::to_string(static_cast<int>(kMaxFilledHoleSpan * 100)) +
               " % of its size across, with a fan of triangles about its centre (flat where the rim "
               "is)"));
  ParamSpec slices = real("slices", "--slices", "Slices", "Slicing", "", a.slices, 2, 4096, 8, "Slices",
                          "slices per direction");
  slices.kind = ParamKind::Integer;
  out.push_back(slices);
  out.push_back(real("interval", "--interval", "Interval", "Slicing", "mm", a.interval, 0, 100000, 0.5,
                     "Interval", "mm between slices; overrides slices (0: slices sets it)"));
  out.push_back(real("tau_a", "--tau-a", "TauA", "Slicing", "", a.tauA, 0, 1, 0.01, "Cylinder error budget",
                     "cylinder error budget, relative to each part's volume (the paper's tauA)"));
  out.push_back(real("tau_m", "--tau-m", "TauM", "Slicing", "", a.tauM, 0, 0.99, 0.01,
                     "Branch merge threshold",
                     "Reeb branch merge threshold, a weight ratio (the paper's tauM)"));
  out.push_back(choice("scheme", "--scheme", "Scheme", "Slicing", {"both", "u", "v"}, "Scheme",
                       "both families, or u / v for one dominant direction"));
  out.push_back(
      real("size", "--size", "Size", "Slicing", "mm", 150, 0, 100000, 10, "Size",
           "scale the model so its longest side is this many mm (0: keep its size; mesh files carry "
           "no unit)"));
  out.push_back(real("height", "--height", "", "Slicing", "mm", 0, 0, 100000, 10, "Height",
                     "scale the model so its height along W (u x v) is this many mm (0: size sets it)"));
  out.push_back(real("time_limit", "--time-limit", "TimeLimit", "Slicing", "s", d.timeLimit, 0, 1e6, 10,
                     "Time limit",
                     "seconds the design may take before its searches stop with the best found, which is "
                     "not called buildable (0: no limit)"));
  const HingeRules& h = a.hinges;
  out.push_back(real("min_hinge_length", "--min-hinge-length", "MinHingeLength", "Hinges", "mm",
                     h.minHingeLength, 0, 1000, 0.5, "Shortest hinge",
                     "mm a hinge must be long to carry load"));
  out.push_back(real("min_slot_edge_distance", "--min-slot-edge-distance", "MinSlotEdgeDistance", "Hinges",
                     "mm", h.minSlotEdgeDistance, 0, 1000, 0.5, "Paper beside a slot",
                     "mm of paper to keep on each side of a slot"));
  out.push_back(real("min_spacing", "--min-spacing", "MinSpacing", "Hinges", "mm", a.stabilize.minSpacing, 0,
                     100000, 0.5, "Closest patches",
                     "mm between two patches of one family that overlap seen along their normal, so paper is "
                     "left between their slots (0: slot width + min slot-edge distance)"));
  out.push_back(real("max_spacing", "--max-spacing", "MaxSpacing", "Hinges", "mm", a.stabilize.maxSpacing, 0,
                     100000, 5, "Farthest patches",
                     "mm; add patches in long cylinders so none is farther apart (0: off)"));
  const SlotParams& s = d.slots;
  out.push_back(real("thickness", "--thickness", "Thickness", "Material", "mm", s.thickness, 0.01, 99.9, 0.05,
                     "Thickness", "mm of material (0.3 for card, 3 for plywood)"));
  out.push_back(real("clearance", "--clearance", "Clearance", "Material", "mm", s.clearance, 0, 99.9, 0.05,
                     "Slot clearance", "mm added to the thickness for the slot width"));
  out.push_back(real("kerf", "--kerf", "Kerf", "Material", "mm", s.kerf, 0, 99.9, 0.01, "Cutter kerf",
                     "mm the cutter removes; cut paths are moved out by half"));
  out.push_back(choice("slot_end", "--slot-end", "SlotEnd", "Material", {"square", "round"}, "Slot ends",
                       "square, or round closed slot ends"));
  out.push_back(choice("u_slots", "--u-slots", "USlots", "Material", {"up", "down"}, "U slots",
                       "up or down: which way U-patches are slotted first (V the other way)"));
  out.push_back(choice("sheet", "--sheet", "SheetSize", "Sheets", {"A4", "A3", "Letter"}, "Sheet",
                       "sheet size: A4, A3, Letter, or WxH in mm (e.g. 600x400)"));
  out.push_back(real("margin", "--margin", "Margin", "Sheets", "mm", 10, 0, 1000, 1, "Sheet margin",
                     "mm kept clear along every sheet edge"));
  out.push_back(real("spacing", "--spacing", "Spacing", "Sheets", "mm", 3, 0, 1000, 1,
                     "Space between patches", "mm between patches on a sheet"));
  out.push_back(flag("rotate", "--no-rotate", "Rotate", "Sheets", true, "Rotate",
                     "patches may be turned by quarters to nest better; off (--no-rotate) keeps every patch "
                     "upright on the sheet (grain, printed textures)"));
  out.push_back(real("fold_angle", "--fold-angle", "FoldAngle", "Assembly", "deg", 90, 1, 90, 5, "Fold angle",
                     "degrees between the families in the 3D assembly: 90 is popped up, small angles fold it "
                     "flat"));
  return out;
}

}  // namespace

const std::vector<ParamSpec>& designParameterSchema() {
  static const std::vector<ParamSpec> schema = make();
  return schema;
}

const ParamSpec& parameterSpec(const std::string& key) {
  for (const ParamSpec& s : designParameterSchema())
    if (s.key == key) return s;
  throw std::out_of_range("no design parameter " + key);
}

}  // namespace sliceform
