# SPDX-License-Identifier: LGPL-2.1-or-later
# The "FreeCAD edit" rows of bench/run.py (issue 17), run by `freecadcmd` (bench/run.py starts
# it with the workbench installed in a throwaway HOME): a parameter edit the way the property
# editor makes it (one transaction, the document recomputed, the transaction closed) on a Sliceform of a mesh and of
# a box minus a cylinder, each edit `repeat` times with a value not used before (a value
# from before would find its design in memory). Times: the recompute, which is what the user
# waits for (TechDraw 0.20 draws its views inside it; 1.0 in threads, after it), and the
# time until every sheet is drawn; and the recompute's time per kind of object, from
# the document observer's timestamps. Job and results are JSON files named by environment
# variables.
import json
import os
import time

import FreeCAD
import Mesh

from PySide import QtCore

from sliceform_app import feature, settling

# FreeCAD 1.0 computes TechDraw's views in threads whose results arrive through Qt's event
# loop, and freecadcmd 1.0 has no Qt application: without one the views would never be drawn
# and "drawn s" would mean nothing (the tests make one the same way).
_qt_application = QtCore.QCoreApplication.instance() or QtCore.QCoreApplication([])
job = json.load(open(os.environ["SLICEFORM_FC_JOB"]))
repeat = job["repeat"]


class Clock:
    """Seconds per kind of object during a recompute: the sliceform, its patches, the sheet
    drawings (a patch on its sheet, its engraving), TechDraw's views, the rest."""

    def __init__(self):
        self.parts, self.t = {}, None

    def slotBeforeRecomputeDocument(self, doc):
        self.t = time.perf_counter()

    def slotRecomputedObject(self, obj):
        now = time.perf_counter()
        kind = getattr(getattr(obj, "Proxy", None), "Type", None) or obj.TypeId
        kind = {"Sliceform": "sliceform", "SliceformPatch": "patches", "SliceformSheetPatch": "sheet drawings",
                "SliceformEngraving": "sheet drawings", "TechDraw::DrawViewPart": "TechDraw views"}.get(kind, "other")
        if self.t is not None:
            self.parts[kind] = self.parts.get(kind, 0.0) + now - self.t
        self.t = now


def median(xs):
    xs = sorted(xs)
    return xs[len(xs) // 2] if len(xs) % 2 else (xs[len(xs) // 2 - 1] + xs[len(xs) // 2]) / 2


def box_minus_cylinder(doc):
    box = doc.addObject("Part::Box", "Box")
    box.Length, box.Width, box.Height = 80, 60, 60
    hole = doc.addObject("Part::Cylinder", "Hole")
    hole.Radius, hole.Height = 15, 100
    hole.Placement.Base = FreeCAD.Vector(40, 30, -20)
    cut = doc.addObject("Part::Cut", "Cut")
    cut.Base, cut.Tool = box, hole
    doc.recompute()
    return cut, {"Radius": (hole, [15.5 + 0.5 * k for k in range(repeat)])}


def mesh(doc, path):
    m = doc.addObject("Mesh::Feature", "Mesh")
    m.Mesh = Mesh.read(path)
    doc.recompute()
    return m, {}


def bench(source_edits, directions, clock):
    doc = FreeCAD.ActiveDocument
    source, edits = source_edits
    t = time.perf_counter()
    sliceform = feature.makeSliceform(source, Directions=directions)
    settling.settle_views()
    out = {"create_s": time.perf_counter() - t, "patches": sliceform.PatchCount, "sheets": sliceform.SheetCount,
           "edits": {}}
    edits = dict({"Thickness": (sliceform, [0.31 + 0.01 * k for k in range(repeat)]),
                  "Clearance": (sliceform, [0.11 + 0.01 * k for k in range(repeat)]),
                  "Slices": (sliceform, [sliceform.Slices + 1 + k for k in range(repeat)]),
                  "Margin": (sliceform, [10.5 + 0.5 * k for k in range(repeat)]),
                  "Kerf": (sliceform, [0.05 + 0.01 * k for k in range(repeat)]),
                  "FoldAngle": (sliceform, [60.0 + 5 * k for k in range(repeat)])}, **edits)
    for prop, (obj, values) in edits.items():
        runs = []
        for value in values:
            clock.parts = {}
            doc.openTransaction("Edit " + prop)
            t = time.perf_counter()
            setattr(obj, prop, value)  # a FoldAngle edit poses the patches here, recomputing nothing
            doc.recompute()
            # Closing the transaction syncs the children (and recomputes the ones it changed)
            # inside the edit's Undo step: the property editor closes it right after.
            doc.commitTransaction()
            recompute = time.perf_counter() - t
            settling.settle_views()
            drawn = time.perf_counter() - t
            runs.append({"recompute_s": recompute, "drawn_s": drawn, "parts_s": dict(clock.parts),
                         "valid": sliceform.isValid()})
        kinds = sorted({k for r in runs for k in r["parts_s"]})
        out["edits"][prop] = {"recompute_s": median([r["recompute_s"] for r in runs]),
                              "drawn_s": median([r["drawn_s"] for r in runs]),
                              "parts_s": {k: median([r["parts_s"].get(k, 0.0) for r in runs]) for k in kinds},
                              "valid": all(r["valid"] for r in runs), "runs": len(runs)}
    return out


results = {"freecad": ".".join(FreeCAD.Version()[:3])}
clock = Clock()
FreeCAD.addDocumentObserver(clock)
# Directions "given" is makeSliceform's default, "auto" the Sliceform command's (it designs in
# several frames and keeps the best).
for name in ["box minus a cylinder"] + job["meshes"]:
    for directions in job["directions"]:
        row = "%s, directions %s" % (name, directions)
        try:
            doc = FreeCAD.newDocument("Edit")
            doc.UndoMode = 1  # as in the GUI
            source = box_minus_cylinder(doc) if name == "box minus a cylinder" else mesh(doc, name)
            results[row] = dict(bench(source, directions, clock), model=name, directions=directions)
            FreeCAD.closeDocument(doc.Name)
        except Exception as e:  # report it; the benchmark goes on without this row
            results[row] = {"model": name, "directions": directions, "error": repr(e)}
FreeCAD.removeDocumentObserver(clock)
json.dump(results, open(os.environ["SLICEFORM_FC_OUT"], "w"), indent=1)
