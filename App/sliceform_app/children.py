# SPDX-License-Identifier: LGPL-2.1-or-later
"""The Sliceform feature's children. They depend on the feature, never the reverse, the
way TechDraw views depend on their source:

- a *patch* (Part::Part2DObjectPython) per patch: its exact outline as a face on its
  plane, with the properties `Sliceform` (link) and `Index`;
- a *sheet patch* (Part::FeaturePython) per patch, linking the patch: the curves that cut
  the patch out of its sheet, in sheet millimetres;
- a TechDraw page per sheet (dynamic properties `Sliceform` and `SheetIndex`) with a
  template of the sheet's size and one view per sheet patch;
- an *engraving* (Part::FeaturePython) per patch, linking the patch: its engraved strokes
  (id, partner labels, leaders) in sheet millimetres, in a view of its own drawn after the
  page's patch views, so that TechDraw's DXF puts them on a layer of their own
  (`<patch>_Engrave`), apart from the cuts (a layer per patch view). A long engraving is in
  several parts (`EngravingPart` 0, 1, ...), each with its view (`<patch>_2_Engrave`, ...):
  TechDraw's face search costs the square of a view's edges (geometry.engraving_parts).

Each child builds its geometry in its own execute() from the design the Sliceform's proxy
holds in memory (designed again on demand, after a reopen). The feature itself never adds,
removes or recomputes other objects: syncing.sync() does, only when the patches or their sheets
differ from what the children show, as a step of its own inside the transaction of the
edit that caused it (a command, the task panel, or the document's recompute).

This module holds the children's features; their classes stay here, where saved documents
name them (`sliceform_app.children.Patch`). lookup.py finds a sliceform's children,
making.py makes and removes them, syncing.py makes them follow the design, observer.py
syncs them inside the edit's transaction."""
import FreeCAD
import Part

from sliceform_app import geometry, lookup, settling

QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP


class _Child:
    """What the children's proxies share: a Type, nothing saved but it, and their inputs as
    read-only properties, (type, name, group, tooltip) each, added where missing."""

    Type = None
    PROPERTIES = ()

    def __init__(self, obj):
        obj.Proxy = self
        self.initProperties(obj)

    def initProperties(self, obj):
        have = obj.PropertiesList
        for kind, name, group, tip in self.PROPERTIES:
            if name not in have:
                obj.addProperty(kind, name, group, tip)
            obj.setEditorMode(name, 1)

    def onDocumentRestored(self, obj):
        self.initProperties(obj)
        settling.views_restored(lookup.views_of(obj))

    def __getstate__(self):
        return {"Type": self.Type}

    def __setstate__(self, state):
        self.built = None

    def dumps(self):
        return self.__getstate__()

    def loads(self, state):
        return None


class Patch(_Child):
    """One patch of a sliceform: its exact outline (slots included) as a face on its plane."""

    Type = "SliceformPatch"
    PROPERTIES = (
        ("App::PropertyLink", "Sliceform", "Patch", QT_TRANSLATE_NOOP("App::Property", "The sliceform this patch belongs to")),
        ("App::PropertyInteger", "Index", "Patch", QT_TRANSLATE_NOOP("App::Property", "Position of the patch in the design")),
        ("App::PropertyString", "PatchId", "Patch", QT_TRANSLATE_NOOP("App::Property", "The id engraved on the patch")),
    )

    def execute(self, obj):
        if not lookup.is_sliceform(obj.Sliceform):
            raise ValueError(QT_TRANSLATE_NOOP("Sliceform", "this patch's sliceform was deleted: delete the patch too"))
        proxy = obj.Sliceform.Proxy
        patches = proxy.flat_patches(obj.Sliceform)
        if obj.Index >= len(patches):
            return  # left over from a larger design until the sync that follows removes it
        # The same design needs no new shape, nor does the same design laid out on another
        # sheet (a sheet, margin or spacing edit): a patch's face does not depend on them.
        built = (proxy.unlaid.get(proxy.key, proxy.key), obj.Index)
        if getattr(self, "built", None) == built and not obj.Shape.isNull():
            return
        shape, placement = proxy.local_faces(obj.Sliceform)[obj.Index]
        # The object's Placement places the shape: during a recompute FreeCAD gives a new
        # Shape the object's Placement, whatever the shape had.
        if obj.Placement != placement:
            obj.Placement = placement
        obj.Shape = shape
        self.built = built


def _on_sheet(shapes, sheets):
    """shapes and two vertices at the sheet's corners, so that the compound's box is the
    sheet (TechDraw centres a view on its shape's box: the view then sits at the sheet's
    centre and the page shows the sheet at 1:1)."""
    corners = [Part.Vertex(0, 0, 0), Part.Vertex(sheets["width"], sheets["height"], 0)]
    # Part.Compound, not Part.makeCompound: FreeCAD 1.0's makeCompound names every element
    # for its topological naming, 1 ms a drawing of 40 strokes against 0.02 ms (72 drawings
    # in a Slices edit on fandisk); nothing refers to a sheet drawing's elements by name.
    return Part.Compound(shapes + corners)


def _left_over(obj, proxy):
    """A sheet drawing left over from a larger design, until the sync that follows removes
    it: emptied where that lets its view draw nothing, so that the sync need not wait for the
    other views to remove it (settling.py)."""
    if settling.BLANK_LEFT_OVERS and not settling.empty(obj.Shape):
        obj.Shape = Part.Compound([])
        proxy.built = None
    proxy.blank = True


class SheetPatch(_Child):
    """A patch as it lies on its sheet, for the TechDraw view that shows it: the curves that
    cut it out, in sheet millimetres, on the sheet's box (_on_sheet)."""

    Type = "SliceformSheetPatch"
    PROPERTIES = (
        ("App::PropertyLink", "Patch", "Patch", QT_TRANSLATE_NOOP("App::Property", "The patch shown on its sheet")),
    )

    def execute(self, obj):
        patch = obj.Patch
        sliceform = getattr(patch, "Sliceform", None)
        if not lookup.is_sliceform(sliceform):
            raise ValueError(QT_TRANSLATE_NOOP("Sliceform", "this drawing's patch or sliceform was deleted"))
        patches = sliceform.Proxy.flat_patches(sliceform)
        drawing = sliceform.Proxy.sheet_drawings(sliceform).get(patches[patch.Index]["id"]) if patch.Index < len(patches) else None
        if drawing is None:
            _left_over(obj, self)
            return
        built = (sliceform.Proxy.key, patch.Index)
        if getattr(self, "built", None) == built and not obj.Shape.isNull():
            return
        obj.Shape = _on_sheet(geometry.patch_cuts(drawing), sliceform.Proxy.sheets(sliceform))
        self.built, self.blank = built, False


class Engraving(_Child):
    """What is engraved on one patch (its id, partner labels and leaders) as it lies on its
    sheet, in sheet millimetres on the sheet's box (_on_sheet), for a view of its own: part
    EngravingPart of geometry.engraving_parts. One a patch, in parts of at most 100 edges,
    not one a sheet: TechDraw looks for faces among a view's edges at a cost that grows with
    the square of their number, and a sheet's labels made its engraving view take 80 % of an
    edit's recompute (docs/decisions.md)."""

    Type = "SliceformEngraving"
    PROPERTIES = (
        ("App::PropertyLink", "Patch", "Engraving", QT_TRANSLATE_NOOP("App::Property", "The patch whose labels these are")),
        ("App::PropertyInteger", "EngravingPart", "Engraving",
         QT_TRANSLATE_NOOP("App::Property", "Which part of the patch's engraving this is (0: the first)")),
    )

    def execute(self, obj):
        patch = obj.Patch
        sliceform = getattr(patch, "Sliceform", None)
        if not lookup.is_sliceform(sliceform):
            raise ValueError(QT_TRANSLATE_NOOP("Sliceform", "this engraving's patch or sliceform was deleted"))
        patches = sliceform.Proxy.flat_patches(sliceform)
        drawing = sliceform.Proxy.sheet_drawings(sliceform).get(patches[patch.Index]["id"]) if patch.Index < len(patches) else None
        parts = geometry.engraving_parts(drawing) if drawing is not None else []
        if obj.EngravingPart >= len(parts):
            _left_over(obj, self)
            return
        built = (sliceform.Proxy.key, patch.Index, obj.EngravingPart, geometry.ENGRAVING_VIEW_EDGES)
        if getattr(self, "built", None) == built and not obj.Shape.isNull():
            return
        obj.Shape = _on_sheet(geometry.stroke_shapes(parts[obj.EngravingPart]), sliceform.Proxy.sheets(sliceform))
        self.built, self.blank = built, False
