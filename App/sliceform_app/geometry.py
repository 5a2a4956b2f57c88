# SPDX-License-Identifier: LGPL-2.1-or-later
"""The core's flat geometry as FreeCAD geometry: line/arc/circle elements become Part
curves."""
import math

import FreeCAD
import Part

V = FreeCAD.Vector


def curve(e):
    """A Part curve in the XY plane for one element (dict from the core)."""
    if e["kind"] == "line":
        return Part.LineSegment(V(e["a"][0], e["a"][1], 0), V(e["b"][0], e["b"][1], 0))
    circle = Part.Circle(V(e["centre"][0], e["centre"][1], 0), V(0, 0, 1), e["radius"])
    if e["kind"] == "circle":
        return circle
    # Part arcs run counter-clockwise from the first angle to the second; a clockwise
    # element is the counter-clockwise arc from its end back to its start.
    first, second = (e["start"], e["end"]) if e["ccw"] else (e["end"], e["start"])
    while second <= first:
        second += 2 * math.pi
    return Part.ArcOfCircle(circle, first, second)


def plane_placement(patch):
    """The placement that maps the patch's plane coordinates (x, y, 0) to 3D."""
    o, x, y, n = (V(*patch[k]) for k in ("origin", "x_axis", "y_axis", "normal"))
    return FreeCAD.Placement(FreeCAD.Matrix(x.x, y.x, n.x, o.x, x.y, y.y, n.y, o.y, x.z, y.z, n.z, o.z, 0, 0, 0, 1))


def local_face(patch, brep):
    """The patch's paper (its face, slots and holes cut) as the core made it, the exact face
    for a BRep source, in the coordinates of the patch's plane, and the placement of that
    plane. Rebuilding it from the flat cut loops fitted B-splines to the polygonised
    free-form edges (26 ms a patch on a box minus a cylinder cut aslant: 1.0 s of a
    Thickness edit) and drew the kerf-compensated cut path, not the paper."""
    shape = Part.Shape()
    shape.importBrepFromString(brep)
    placement = plane_placement(patch)
    shape.transformShape(placement.inverse().toMatrix(), True)  # a copy: the geometry moves
    return shape, placement


def polyline(points):
    """A run of straight segments through points as one edge: a B-spline of degree 1, which
    is the polyline exactly (a pole at every corner, a knot of multiplicity 1 at each inner
    pole). A single segment stays a line."""
    if len(points) == 2:
        return Part.LineSegment(points[0], points[1])
    spline = Part.BSplineCurve()
    n = len(points)
    spline.buildFromPolesMultsKnots(points, [2] + [1] * (n - 2) + [2], list(range(n)), False, 1)
    return spline


def loop_edges(loop):
    """One cut loop as edges: each run of consecutive line elements one polyline(), arcs and
    circles as themselves. A loop of lines only is one closed edge."""

    def point(p):
        return V(p[0], p[1], 0)

    if all(e["kind"] == "line" for e in loop):
        return [polyline([point(e["a"]) for e in loop] + [point(loop[0]["a"])]).toShape()]
    # Walked from just after a curve, the loop ends on a curve: no run wraps past its end.
    start = next(i for i, e in enumerate(loop) if e["kind"] != "line") + 1
    edges, run = [], []
    for e in loop[start:] + loop[:start]:
        if e["kind"] == "line":
            run.append(e)
            continue
        if run:
            edges.append(polyline([point(r["a"]) for r in run] + [point(run[-1]["b"])]).toShape())
            run = []
        edges.append(curve(e).toShape())
    return edges


def patch_cuts(patch):
    """One patch's cut curves as drawn on its sheet, in sheet millimetres on the XY plane: a
    few edges a loop (loop_edges). TechDraw 0.20 and 1.0 look for faces among a view's edges
    at a cost that grows with the square of their number: as an edge a segment, fandisk's
    27 patch views took 538 ms to draw, with these 143 ms (docs/decisions.md)."""
    return [edge for loop in patch["cut"] for edge in loop_edges(loop)]


# A patch's engraving goes to TechDraw in views of at most this many edges. TechDraw 0.20
# looks for faces among a view's edges by computing, for each edge, the box of every other:
# fandisk's largest engraving with directions auto (460 edges) drew in 721 ms as one view
# and 97 ms as six (docs/decisions.md).
ENGRAVING_VIEW_EDGES = 100


def engraving_parts(patch):
    """One patch's engraved strokes (its id, partner labels, marks) as drawn on its sheet, in
    consecutive groups of at most ENGRAVING_VIEW_EDGES edges (a longer stroke alone), one
    group a TechDraw view; at least one group."""
    parts, edges = [[]], 0
    for stroke in patch["engrave"]:
        if len(stroke) < 2:
            continue
        if parts[-1] and edges + len(stroke) - 1 > ENGRAVING_VIEW_EDGES:
            parts.append([])
            edges = 0
        parts[-1].append(stroke)
        edges += len(stroke) - 1
    return parts


def stroke_shapes(strokes):
    """Engraved strokes as polylines on the XY plane."""
    return [Part.makePolygon([V(x, y, 0) for x, y in stroke]) for stroke in strokes]
