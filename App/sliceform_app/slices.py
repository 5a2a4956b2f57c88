# SPDX-License-Identifier: LGPL-2.1-or-later
"""Cross-sections of a document object along U and V, as FreeCAD shapes: the first use
of the core inside FreeCAD (the Sliceform_Slices command)."""
import Part

from sliceform_app import native, shapes

DEFAULT_DIRECTIONS = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0))


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def slice_object(obj, count=16, directions=DEFAULT_DIRECTIONS):
    """Slice sets of `obj` along U and V: a list of two dicts as the core returns them,
    with, per slice, the section as a Part shape under "shape"."""
    core = native()
    u, v = directions
    w = _cross(u, v)
    result = []
    for normal in (u, v):
        if shapes.is_mesh(obj):
            points, triangles = shapes.mesh_lists_of(obj)
            sliced = core.slice_mesh(points, triangles, normal, w, count)
            for s in sliced["slices"]:
                s["shape"] = Part.makeCompound(shapes.faces_from_loops(s["loops"], sliced, s["position"]))
        else:
            sliced = core.slice_brep(shapes.brep_of(obj), normal, w, count)
            for s in sliced["slices"]:
                s["shape"] = shapes.shape_from_brep(s["faces"])
        result.append(sliced)
    return result


def make_slices(doc, obj, count=16):
    """Adds a Part::Feature holding every U and V section of `obj` as one compound."""
    sets = slice_object(obj, count)
    faces = [f for sliced in sets for s in sliced["slices"] for f in s["shape"].Faces]
    feature = doc.addObject("Part::Feature", "Slices")
    feature.Label = "{} slices".format(obj.Label)
    feature.Shape = Part.makeCompound(faces)
    return feature
