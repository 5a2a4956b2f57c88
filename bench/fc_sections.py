# SPDX-License-Identifier: LGPL-2.1-or-later
# FreeCAD's reference for the slicing floor, run by `freecadcmd` (bench/run.py starts it):
# each model is read, scaled about the origin so its longest side is `size` mm (what
# `sliceform design --size` does), and cut by the same 2 x n planes as our slices: normals
# X and Y, at the centres of n equal cells of the bounding box along each (uniformPositions
# in the core). Meshes use Mesh.crossSections; CAD files Part's Shape.slices (exact).
# Only the cutting is timed. Job and results are JSON files named by environment variables.
import json
import os
import time

import FreeCAD
import Mesh
import Part

job = json.load(open(os.environ["SLICEFORM_FC_JOB"]))
n, size, repeat = job["slices"], job["size"], job["repeat"]
CAD = (".step", ".stp", ".iges", ".igs", ".brep", ".brp")


def cells(lo, hi):
    return [lo + (i + 0.5) * (hi - lo) / n for i in range(n)]


results = {}
for path in job["models"]:
    try:
        cad = path.lower().endswith(CAD)
        obj = Part.read(path) if cad else Mesh.read(path)
        bb = obj.BoundBox
        s = size / max(bb.XLength, bb.YLength, bb.ZLength)
        if cad:
            obj.scale(s, FreeCAD.Vector(0, 0, 0))
        else:
            m = FreeCAD.Matrix()
            m.scale(s, s, s)
            obj.transform(m)
        bb = obj.BoundBox
        xs, ys = cells(bb.XMin, bb.XMax), cells(bb.YMin, bb.YMax)
        X, Y, O = FreeCAD.Vector(1, 0, 0), FreeCAD.Vector(0, 1, 0), FreeCAD.Vector(0, 0, 0)
        times, pieces = [], 0
        for _ in range(repeat):
            t = time.perf_counter()
            if cad:
                pieces = len(obj.slices(X, xs).Wires) + len(obj.slices(Y, ys).Wires)
            else:
                planes = [(X * x, X) for x in xs] + [(Y * y, Y) for y in ys]
                pieces = sum(len(s) for s in obj.crossSections(planes))
            times.append(time.perf_counter() - t)
        times.sort()
        results[path] = {"method": "Part.Shape.slices" if cad else "Mesh.crossSections",
                         "median_s": times[len(times) // 2], "times_s": times, "pieces": pieces,
                         "facets": None if cad else obj.CountFacets}
    except Exception as e:  # report it; the benchmark goes on without this figure
        results[path] = {"error": repr(e)}
json.dump(results, open(os.environ["SLICEFORM_FC_OUT"], "w"), indent=1)
