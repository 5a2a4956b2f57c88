// SPDX-License-Identifier: LGPL-2.1-or-later
// sliceform_native: the core for Python. Shapes cross as BREP strings (what FreeCAD's
// Part.Shape.exportBrepToString gives), meshes as lists of points and index triples, and
// results come back as plain dicts and lists, so the FreeCAD side needs no C++ types.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <sstream>
#include <string>
#include <vector>

#include "bindings/convert.hpp"
#include "model/model.hpp"
#include "slicing/brep_slicer.hpp"
#include "slicing/mesh_slicer.hpp"
#include "support/error.hpp"
#include "support/occt_guard.hpp"
#include "support/occt_statics.hpp"

namespace py = pybind11;
using namespace sliceform;

namespace sliceform {
void bindDesign(py::module_& m);
}

namespace {

SliceFrame frameFor(const Triple& normal, const Triple& up) {
  return makeSliceFrame(toVec(normal), toVec(up));
}

py::list loopsOf(const Region2d& region) {
  py::list loops;
  for (const Region2d::Loop& loop : region.loops()) {
    py::list points;
    for (const Vec2& p : loop) points.append(py::make_tuple(p.x, p.y));
    loops.append(points);
  }
  return loops;
}

py::dict frameDict(const SliceFrame& frame) {
  py::dict d;
  d["normal"] = toTuple(frame.normal);
  d["x_axis"] = toTuple(frame.xAxis);
  d["y_axis"] = toTuple(frame.yAxis);
  return d;
}

py::dict sliceBrepString(const std::string& brep, const Triple& normal, const Triple& up, int count,
                         double deflection) {
  const Model model = modelFromShape(shapeFromBrep(brep), "the shape");
  const SliceFrame frame = frameFor(normal, up);
  const std::vector<double> positions = slicePositions(model.mesh, frame, count);
  std::vector<ExactSlice> slices;
  {
    py::gil_scoped_release release;
    slices = sliceBrep(model.shape, frame, positions,
                       deflection > 0 ? deflection : exactDeflection(model.meshDeflection));
  }
  py::dict result = frameDict(frame);
  py::list out;
  for (const ExactSlice& s : slices) {
    py::dict d;
    d["position"] = s.position;
    d["area"] = s.area;
    d["loops"] = loopsOf(s.region);
    d["faces"] = brepFromShape(s.faces);
    out.append(d);
  }
  result["slices"] = out;
  return result;
}

py::dict sliceMeshLists(const std::vector<Triple>& points, const std::vector<Index3>& triangles,
                        const Triple& normal, const Triple& up, int count) {
  const Model model = modelFromMesh(meshFromLists(points, triangles), "the mesh");
  requireClosed(model);
  const SliceFrame frame = frameFor(normal, up);
  const std::vector<double> positions = slicePositions(model.mesh, frame, count);
  SliceSet set;
  {
    py::gil_scoped_release release;
    set = sliceMesh(model.mesh, frame, positions);
  }
  py::dict result = frameDict(frame);
  py::list out;
  for (const Slice& s : set.slices) {
    py::dict d;
    d["position"] = s.position;
    d["area"] = s.region.area();
    d["loops"] = loopsOf(s.region);
    out.append(d);
  }
  result["slices"] = out;
  return result;
}

py::dict meshTopology(const std::vector<Triple>& points, const std::vector<Index3>& triangles) {
  const Mesh mesh = meshFromLists(points, triangles);
  validateMesh(mesh, "the mesh");
  const MeshTopology topo = analyseTopology(weldExact(mesh));
  py::dict d;
  d["closed"] = topo.closed();
  d["boundary_edges"] = topo.boundaryEdges;
  d["non_manifold_edges"] = topo.nonManifoldEdges;
  d["holes"] = topo.holes;
  d["message"] = topo.closed() ? std::string("the mesh is closed") : topo.describe();
  return d;
}

py::dict readModelFile(const std::string& path) {
  const Model model = readModel(path);
  py::dict d;
  d["kind"] = model.kind == SourceKind::Brep ? "brep" : "mesh";
  d["triangles"] = model.mesh.triangles.size();
  d["bounds"] = py::make_tuple(toTuple(model.bounds.min), toTuple(model.bounds.max));
  if (model.kind == SourceKind::Brep) d["brep"] = brepFromShape(model.shape);
  return d;
}

// Reads a BREP string and writes it back: the shape FreeCAD gets from the core.
std::string brepRoundTrip(const std::string& brep) {
  return brepFromShape(shapeFromBrep(brep));
}

}  // namespace

PYBIND11_MODULE(sliceform_native, m) {
  m.doc() = "Sliceform core: model reading, slicing and design (lengths in mm)";
  m.attr("__version__") = SLICEFORM_VERSION;
  // sliceform_native.Error carries the core's message. register_exception keeps the Python
  // type alive safely across pybind11 versions (2.10 on Debian 12, 2.13 on Debian 13, where
  // calling a static py::exception object is deprecated).
  py::register_exception<Error>(m, "Error");

  m.def("slice_brep", &sliceBrepString, py::arg("brep"), py::arg("normal"), py::arg("up"), py::arg("count"),
        py::arg("deflection") = 0.0,
        "Exact sections of the solids in a BREP string at `count` planes normal to `normal`, "
        "with `up` as the 2D y axis. Returns the frame and, per slice, position, area, "
        "polygon loops (mm, outer counter-clockwise) and the faces as a BREP string.");
  m.def("slice_mesh", &sliceMeshLists, py::arg("points"), py::arg("triangles"), py::arg("normal"),
        py::arg("up"), py::arg("count"),
        "Sections of a closed triangle mesh, as slice_brep but without faces.");
  m.def("mesh_topology", &meshTopology, py::arg("points"), py::arg("triangles"),
        "Boundary and non-manifold edge counts of a triangle mesh, and whether it is closed.");
  m.def("read_model", &readModelFile, py::arg("path"),
        "Reads STEP, IGES, BREP, STL, OBJ or OFF; returns kind, triangle count, bounds and, "
        "for CAD files, the solids as a BREP string.");
  bindDesign(m);
  m.def("brep_round_trip", &brepRoundTrip, py::arg("brep"), "Reads a BREP string and writes it back.");
  m.def(
      "occt_settings",
      [] {
        py::dict out;
        for (const std::string& line : StaticsSnapshot().describe()) {
          const size_t eq = line.find('=');
          out[py::str(line.substr(0, eq))] = line.substr(eq + 1);
        }
        return out;
      },
      "OpenCASCADE's process-wide data-exchange settings (Interface_Static), name -> value "
      "as text: shared with FreeCAD's own STEP/IGES import and export, and left as they were "
      "by every core function.");
}
