# SPDX-License-Identifier: LGPL-2.1-or-later
"""Conversions between FreeCAD objects and what the core takes: BREP strings for shapes,
point and index lists for meshes. Shapes are taken in global placement."""
import FreeCAD
import Part


def is_mesh(obj):
    return obj.isDerivedFrom("Mesh::Feature")


def placed_shape(obj):
    """The object's shape, placed globally (the placements of the object and its
    containers)."""
    shape = Part.getShape(obj)
    if shape.isNull():
        raise ValueError(FreeCAD.Qt.translate("Sliceform", "{} has no shape").format(obj.Label))
    return shape


def brep_of(obj, size=0.0):
    """The object's shape, placed globally, as a BREP string; with a size > 0, scaled about
    the centre of its box so that its longest side is that long."""
    return brep_of_shape(placed_shape(obj), size)


def brep_of_shape(shape, size=0.0):
    """brep_of for a shape placed already."""
    box = shape.BoundBox
    longest = max(box.XLength, box.YLength, box.ZLength)
    if size > 0 and longest > 0:
        shape = shape.copy()
        shape.scale(size / longest, box.Center)
    return shape.exportBrepToString()


def mesh_lists_of(obj):
    """(points, triangles) of a Mesh::Feature, placed globally. Meshes go to the core as
    triangles; converting them to a BRep first would make every later step crawl."""
    mesh = obj.Mesh.copy()
    mesh.Placement = obj.getGlobalPlacement()
    points, facets = mesh.Topology  # points come out with the placement applied
    return [tuple(p) for p in points], [tuple(f) for f in facets]


def shape_from_brep(text):
    shape = Part.Shape()
    if text:
        shape.importBrepFromString(text)
    return shape


def faces_from_loops(loops, frame, position):
    """Planar faces from 2D loops (outer counter-clockwise, holes clockwise) of a slice."""
    n, x, y = (FreeCAD.Vector(*frame[k]) for k in ("normal", "x_axis", "y_axis"))
    origin = n * position
    wires = []
    for loop in loops:
        points = [origin + x * u + y * v for u, v in loop]
        wires.append(Part.makePolygon(points + points[:1]))
    if not wires:
        return []
    # Bullseye nests holes in outers by containment, whatever the order of the wires.
    made = Part.makeFace(wires, "Part::FaceMakerBullseye")
    return made.Faces
