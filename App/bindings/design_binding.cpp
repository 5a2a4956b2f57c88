// SPDX-License-Identifier: LGPL-2.1-or-later
// sliceform_native.design(): the whole pipeline for the FreeCAD feature. Parameters come as
// a dict with the CLI's names (lengths in mm, angles in degrees); the result is a Design
// object that hands out the report, the assembly at any fold angle, the flat patches for
// sketches, the sheets for TechDraw, and writes the same files as `sliceform design -o`.
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <memory>
#include <string>

#include "assembly/fold.hpp"
#include "bindings/convert.hpp"
#include "frames/scaffold.hpp"
#include "layout/layout.hpp"
#include "model/model.hpp"
#include "output/design_files.hpp"
#include "output/report_json.hpp"
#include "pipeline/design.hpp"
#include "pipeline/directions.hpp"
#include "pipeline/parameter_schema.hpp"
#include "realization/slots.hpp"
#include "support/error.hpp"

namespace py = pybind11;

namespace sliceform {
namespace {

// The parameters of one run, read from the dict; unknown keys are an error (a misspelt
// property must not be ignored silently).
struct Run {
  DesignParams params;
  double size = 0, height = 0;
  bool autoDirections = false;  // "directions": "auto" (u and v are then ignored)
  bool fillHoles = false;       // every hole of a mesh source filled, not only small ones
};

template <typename T>
void take(py::dict& d, const char* key, T& value) {
  if (!d.contains(key)) return;
  value = d[key].cast<T>();
  d.attr("pop")(key);
}

Run readParams(py::dict given) {
  py::dict d(given.attr("copy")());
  Run run;
  ArrangementParams& a = run.params.arrangement;
  Triple u{1, 0, 0}, v{0, 1, 0};
  take(d, "u", u);
  take(d, "v", v);
  a.u = toVec(u);
  a.v = toVec(v);
  take(d, "slices", a.slices);
  take(d, "interval", a.interval);
  take(d, "tau_a", a.tauA);
  take(d, "tau_m", a.tauM);
  take(d, "min_hinge_length", a.hinges.minHingeLength);
  take(d, "min_slot_edge_distance", a.hinges.minSlotEdgeDistance);
  take(d, "max_spacing", a.stabilize.maxSpacing);
  take(d, "min_spacing", a.stabilize.minSpacing);
  take(d, "time_limit", run.params.timeLimit);
  std::string scheme = "both", slotEnd = "square", uSlots = "up", sheet = "A4";
  take(d, "scheme", scheme);
  if (scheme != "both" && scheme != "u" && scheme != "v")
    throw Error(ErrorKind::BadParameter, "the scheme must be both, u or v, not " + scheme);
  a.stabilize.scheme = scheme == "u" ? Scheme::DominantU : scheme == "v" ? Scheme::DominantV : Scheme::Both;
  SlotParams& s = run.params.slots;
  take(d, "thickness", s.thickness);
  take(d, "clearance", s.clearance);
  take(d, "kerf", s.kerf);
  take(d, "slot_end", slotEnd);
  if (slotEnd != "square" && slotEnd != "round")
    throw Error(ErrorKind::BadParameter, "the slot end must be square or round, not " + slotEnd);
  s.end = slotEnd == "round" ? SlotEnd::Round : SlotEnd::Square;
  take(d, "u_slots", uSlots);
  s.uUp = uSlots != "down";
  double margin = parameterSpec("margin").value, spacing = parameterSpec("spacing").value;
  bool rotate = parameterSpec("rotate").value != 0;
  take(d, "sheet", sheet);
  take(d, "margin", margin);
  take(d, "spacing", spacing);
  take(d, "rotate", rotate);
  run.params.sheet = sheetSpec(sheet, margin, spacing);
  run.params.sheet.rotate = rotate;
  std::string directions = "given";
  take(d, "directions", directions);
  if (directions != "given" && directions != "auto")
    throw Error(ErrorKind::BadParameter, "the directions must be given or auto, not " + directions);
  run.autoDirections = directions == "auto";
  take(d, "fill_holes", run.fillHoles);
  take(d, "size", run.size);
  take(d, "height", run.height);
  if (run.autoDirections && run.height != 0)
    throw Error(ErrorKind::BadParameter, "height measures along W, which directions auto chooses: give size");
  if (!d.empty())
    throw Error(ErrorKind::BadParameter,
                "unknown design parameter " + py::str(d.begin()->first).cast<std::string>());
  return run;
}

Model sourceModel(const py::dict& source, bool fillEveryHole) {
  const std::string name = source.contains("name") ? source["name"].cast<std::string>() : "the source";
  if (source.contains("brep")) return modelFromShape(shapeFromBrep(source["brep"].cast<std::string>()), name);
  if (source.contains("points")) {
    Model model = modelFromMesh(meshFromLists(source["points"].cast<std::vector<Triple>>(),
                                              source["triangles"].cast<std::vector<Index3>>()),
                                name, fillEveryHole);
    requireClosed(model);
    return model;
  }
  throw Error(ErrorKind::BadInput, name + ": the source holds neither a shape nor a mesh");
}

// What Python holds: the sized model (shared with the designs made again from this one),
// how it was sized, the parameters and the design made from them.
struct PyDesign {
  std::shared_ptr<const Model> model;
  double size = 0, height = 0;
  DesignParams params;
  Design design;
};

// The stages run without the GIL; the progress callback takes it back for its call. It
// refers to `progress`, which must outlive it (no reference count is touched without the GIL).
Progress progressOf(const py::object& progress) {
  if (progress.is_none()) return {};
  return [&progress](const char* stage) {
    py::gil_scoped_acquire gil;
    if (!progress(stage).cast<bool>()) throw Error(ErrorKind::Cancelled, "cancelled by the user");
  };
}

// Designs `run` on `model`; `earlier`, a design of the same model, lends its first stages.
std::shared_ptr<PyDesign> designed(std::shared_ptr<const Model> model, const Run& run,
                                   const py::object& progress, const PyDesign* earlier) {
  auto result = std::make_shared<PyDesign>();
  result->model = std::move(model);
  result->size = run.size;
  result->height = run.height;
  result->params = run.params;
  const Progress report = progressOf(progress);
  py::gil_scoped_release release;
  if (run.autoDirections) {
    DirectionChoice choice;
    result->design = designInBestFrame(*result->model, result->params, choice, report, {}, nullptr,
                                       earlier ? &earlier->design : nullptr);
    // As if given: the report's parameters and everything after carry them.
    result->params.arrangement.u = choice.trials[choice.chosen].u;
    result->params.arrangement.v = choice.trials[choice.chosen].v;
  } else {
    result->design =
        runDesign(*result->model, result->params, report, {}, nullptr, earlier ? &earlier->design : nullptr);
  }
  return result;
}

py::dict element(const CutElement& e) {
  py::dict d;
  switch (e.kind) {
    case CutElement::Kind::Line:
      d["kind"] = "line";
      break;
    case CutElement::Kind::Arc:
      d["kind"] = "arc";
      break;
    case CutElement::Kind::Circle:
      d["kind"] = "circle";
      break;
  }
  d["a"] = py::make_tuple(e.a.x, e.a.y);
  d["b"] = py::make_tuple(e.b.x, e.b.y);
  if (e.kind != CutElement::Kind::Line) {
    d["centre"] = py::make_tuple(e.centre.x, e.centre.y);
    d["radius"] = e.radius;
    d["start"] = e.start;
    d["end"] = e.end;
    d["ccw"] = e.ccw;
  }
  return d;
}

py::list loopsOf(const std::vector<CutLoop>& loops) {
  py::list out;
  for (const CutLoop& loop : loops) {
    py::list elements;
    for (const CutElement& e : loop) elements.append(element(e));
    out.append(elements);
  }
  return out;
}

py::list strokesOf(const std::vector<Stroke>& strokes) {
  py::list out;
  for (const Stroke& s : strokes) {
    py::list points;
    for (const Vec2& p : s) points.append(py::make_tuple(p.x, p.y));
    out.append(points);
  }
  return out;
}

py::list flatPatches(const PyDesign& self) {
  const Arrangement& a = self.design.arrangement;
  py::list out;
  for (size_t k = 0; k < self.design.layout.patches.size(); ++k) {
    const FlatPatch& flat = self.design.layout.patches[k];
    const PatchPlane plane = patchPlane(a, flat.patch);
    py::dict d;
    d["id"] = flat.id;
    d["family"] = flat.family == Family::U ? "U" : "V";
    d["exact"] = self.design.patches[flat.patch].exact;
    d["origin"] = toTuple(plane.origin);
    d["normal"] = toTuple(plane.normal);
    d["x_axis"] = toTuple(plane.xAxis);
    d["y_axis"] = toTuple(plane.yAxis);
    d["loops"] = loopsOf(flat.cut);
    std::vector<Stroke> strokes = flat.name.strokes;
    for (const Label& l : flat.partners) strokes.insert(strokes.end(), l.strokes.begin(), l.strokes.end());
    strokes.insert(strokes.end(), flat.stepLabel.strokes.begin(), flat.stepLabel.strokes.end());
    d["step"] = flat.step;
    d["engrave"] = strokesOf(strokes);
    out.append(d);
  }
  return out;
}

py::dict sheets(const PyDesign& self) {
  const SheetLayout& layout = self.design.layout;
  py::dict d;
  d["name"] = layout.sheet.name;
  d["width"] = layout.sheet.width;
  d["height"] = layout.sheet.height;
  d["margin"] = layout.sheet.margin;
  // Per sheet, its patches one by one: TechDraw's hidden-line pass grows much faster than
  // the edge count, so the workbench gives each patch a view of its own.
  py::list pages;
  for (int s = 0; s < layout.packing.sheets; ++s) pages.append(py::list());
  for (size_t k = 0; k < layout.patches.size(); ++k) {
    const Placement& at = layout.packing.placements[k];
    const SheetDrawing drawing = placedDrawing(layout.patches[k], at);
    py::dict patch;
    patch["id"] = layout.patches[k].id;
    patch["cut"] = loopsOf(drawing.cut);
    patch["engrave"] = strokesOf(drawing.engrave);
    pages[at.sheet].cast<py::list>().append(patch);
  }
  d["sheets"] = pages;
  return d;
}

}  // namespace

void bindDesign(py::module_& m) {
  py::class_<PyDesign, std::shared_ptr<PyDesign>>(m, "Design", "A designed sliceform (see design())")
      .def(
          "report_json", [](const PyDesign& d) { return reportJson(*d.model, d.params, d.design).dump(1); },
          "report.json's text (docs/report-format.md)")
      .def(
          "timings",
          [](const PyDesign& d) {
            py::list out;
            for (const StageTime& t : d.design.timings) out.append(py::make_tuple(t.stage, t.ms));
            return out;
          },
          "(stage, milliseconds) per stage")
      .def(
          "assembly",
          [](const PyDesign& d, double theta) {
            if (!(theta > 0 && theta <= 90))
              throw Error(ErrorKind::BadParameter, "the fold angle must be in (0, 90] degrees");
            return brepFromShape(assemble(d.design.arrangement, d.design.patches, theta));
          },
          py::arg("fold_angle") = 90.0,
          "The assembled sliceform at a fold angle in degrees (90: popped up) as a BREP string: a "
          "compound of one face per patch, in the source's coordinates (after sizing)")
      .def(
          "fold_transforms",
          [](const PyDesign& d, double theta) {
            py::list out;
            for (const FlatPatch& flat : d.design.layout.patches) {
              const gp_Trsf t = foldTransform(d.design.arrangement, flat.patch, theta);
              py::list m;
              for (int r = 1; r <= 3; ++r)
                for (int c = 1; c <= 4; ++c) m.append(t.Value(r, c));
              for (const double v : {0.0, 0.0, 0.0, 1.0}) m.append(v);
              out.append(m);
            }
            return out;
          },
          py::arg("fold_angle") = 90.0,
          "Per patch, in flat_patches' order: where the fold angle in degrees (90: popped up) moves "
          "it from its popped-up pose, as the 16 numbers of a 4 x 4 matrix, row by row: "
          "assembly(angle)'s face of the patch is patch_faces()'s moved so")
      .def(
          "patch_faces",
          [](const PyDesign& d) {
            py::list out;
            for (const FlatPatch& flat : d.design.layout.patches)
              out.append(brepFromShape(d.design.patches[flat.patch].shape));
            return out;
          },
          "Per patch, in flat_patches' order: its paper (slots cut) as a BREP string, the exact face "
          "where the source is a BRep, at the popped-up pose in the source's coordinates (after "
          "sizing): the faces of assembly(90)")
      .def("flat_patches", &flatPatches,
           "Per patch: id, family, exact (from the BRep's exact sections), its plane (origin, normal, "
           "x_axis, y_axis) and the cut loops in "
           "plane coordinates as line/arc/circle elements, and the engraved label strokes")
      .def("sheets", &sheets,
           "The nested sheets: size and, per sheet, a list of its patches, each with id, cut loops "
           "and engraved strokes in sheet coordinates")
      .def(
          "relaid",
          [](const PyDesign& d, const py::dict& layoutParams) {
            // Only the sheet or the kerf changed: the same patches, flattened and labelled as
            // they were, nested again or their cut paths drawn again (laidOutAgain). The keys
            // are read as design() reads them (defaults for any not given).
            for (const auto& item : layoutParams) {
              const std::string key = py::str(item.first);
              if (key != "sheet" && key != "margin" && key != "spacing" && key != "rotate" && key != "kerf")
                throw Error(ErrorKind::BadParameter,
                            "relaid() takes the sheet's parameters and the kerf only, not " + key);
            }
            const Run run = readParams(layoutParams);
            auto result = std::make_shared<PyDesign>(d);
            result->params.sheet = run.params.sheet;
            result->params.slots.kerf = run.params.slots.kerf;
            checkSlotParams(result->params.slots);
            result->design.realization.params.kerf = run.params.slots.kerf;
            py::gil_scoped_release release;
            const auto start = std::chrono::steady_clock::now();
            result->design.layout =
                laidOutAgain(layoutInput(result->design), result->design.layout, result->params.sheet);
            for (StageTime& t : result->design.timings)
              if (t.stage == "layout")
                t.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                           .count();
            return result;
          },
          py::arg("layout_params"),
          "The same design laid out again: `layout_params` holds sheet, margin, spacing, rotate and "
          "kerf as design() takes them (a sheet, margin or kerf edit needs no new design)")
      .def(
          "redesigned",
          [](const PyDesign& d, const py::dict& params, const py::object& progress) {
            const Run run = readParams(params);
            const bool sized = run.height != 0
                                   ? run.height == d.height && !run.autoDirections &&
                                         cross(run.params.arrangement.u, run.params.arrangement.v) ==
                                             cross(d.params.arrangement.u, d.params.arrangement.v)
                                   : d.height == 0 && run.size == d.size;
            if (!sized)
              throw Error(
                  ErrorKind::BadParameter,
                  "redesigned() takes the size and height the design was made at: a new size needs design()");
            if (run.fillHoles != d.model->everyHoleFilled && d.model->kind == SourceKind::Mesh)
              throw Error(
                  ErrorKind::BadParameter,
                  "redesigned() takes the holes filled as the design had them: fill_holes needs design()");
            return designed(d.model, run, progress, &d);
          },
          py::arg("params"), py::arg("progress") = py::none(),
          "The same source designed with other parameters (as design() takes them, the same size and "
          "height): the stages whose inputs did not change are taken from this design, as a FreeCAD "
          "edit of Thickness leaves the slices, Reeb graphs and cylinders as they were")
      .def(
          "write_files",
          [](const PyDesign& d, const std::string& folder, double theta) {
            const DesignFiles files = writeDesignFiles(*d.model, d.params, d.design, folder, theta);
            py::dict out;
            out["written"] = files.written;
            out["removed"] = files.removed;
            return out;
          },
          py::arg("folder"), py::arg("fold_angle") = 90.0,
          "Writes the same files as `sliceform design -o FOLDER`; returns their names");

  m.def(
      "parameter_schema",
      [] {
        py::list out;
        for (const ParamSpec& s : designParameterSchema()) {
          py::dict d;
          d["key"] = s.key, d["option"] = s.option, d["property"] = s.property, d["group"] = s.group;
          const char* kinds[] = {"real", "integer", "bool", "choice", "direction"};
          d["kind"] = kinds[static_cast<int>(s.kind)];
          d["unit"] = s.unit;
          switch (s.kind) {
            case ParamKind::Integer:
              d["default"] = static_cast<long>(s.value);
              break;
            case ParamKind::Bool:
              d["default"] = s.value != 0;
              break;
            case ParamKind::Choice:
              d["default"] = s.choices.front();
              break;
            case ParamKind::Direction:
              d["default"] = py::tuple(py::cast(s.direction));
              break;
            default:
              d["default"] = s.value;
          }
          d["choices"] = s.choices;
          d["min"] = s.min, d["max"] = s.max, d["step"] = s.step;
          d["label"] = s.label, d["help"] = s.help;
          out.append(d);
        }
        return out;
      },
      "The design's parameters, one dict each: key (this module's parameter), option (the CLI's), "
      "property (FreeCAD's), group, kind (real, integer, bool, choice, direction), unit, default, "
      "choices, min, max (what the core accepts), step, label and help");
  m.def(
      "design",
      [](const py::dict& source, const py::dict& params, const py::object& progress) {
        const Run run = readParams(params);
        Model model = sourceModel(source, run.fillHoles);
        if (run.height != 0) {
          model =
              scaledToHeight(model, cross(run.params.arrangement.u, run.params.arrangement.v), run.height);
        } else if (run.size != 0) {
          model = scaledToSize(model, run.size);
        }
        return designed(std::make_shared<const Model>(std::move(model)), run, progress, nullptr);
      },
      py::arg("source"), py::arg("params") = py::dict(), py::arg("progress") = py::none(),
      "Designs a sliceform. `source`: {'brep': BREP string} or {'points': [(x, y, z)], "
      "'triangles': [(i, j, k)]}, with an optional 'name' for messages. `params`: the design "
      "command's options by name (u, v, slices, interval, tau_a, tau_m, scheme, "
      "min_hinge_length, min_slot_edge_distance, max_spacing, min_spacing, time_limit, thickness, clearance, "
      "kerf, "
      "slot_end, u_slots, sheet, margin, spacing, rotate, size, height, directions: given or auto). "
      "`progress(stage)` is "
      "called before each stage; returning False cancels the run (Error 'cancelled').");
}

}  // namespace sliceform
