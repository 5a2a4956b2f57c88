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
removes or recomputes other objects: sync() does, only when the patches or their sheets
differ from what the children show, as a step of its own inside the transaction of the
edit that caused it (a command, the task panel, or the document's recompute)."""
import os
import time

import FreeCAD
import Part

from sliceform_app import geometry

V = FreeCAD.Vector


QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP


# ---------------------------------------------------------------------------------------------
# Which objects are whose


def is_sliceform(obj):
    from sliceform_app import feature

    return obj is not None and isinstance(getattr(obj, "Proxy", None), feature.Sliceform)


def _proxy_type(obj):
    return getattr(getattr(obj, "Proxy", None), "Type", None)


def patches_of(sliceform):
    """The patch children of a sliceform, by index."""
    found = [o for o in sliceform.InList if _proxy_type(o) == "SliceformPatch" and o.Sliceform == sliceform]
    return sorted(found, key=lambda o: o.Index)


def sheet_patch_of(patch):
    for o in patch.InList:
        if _proxy_type(o) == "SliceformSheetPatch" and o.Patch == patch:
            return o
    return None


def pages_of(sliceform):
    """The TechDraw pages of a sliceform, by sheet."""
    found = [
        o
        for o in sliceform.InList
        if o.TypeId == "TechDraw::DrawPage" and getattr(o, "Sliceform", None) == sliceform
    ]
    return sorted(found, key=lambda o: o.SheetIndex)


def engraving_parts_of(patch):
    """The engraving children of a patch, by part."""
    found = [o for o in patch.InList if _proxy_type(o) == "SliceformEngraving" and getattr(o, "Patch", None) == patch]
    return sorted(found, key=lambda o: getattr(o, "EngravingPart", 0))


def engraving_of(patch):
    """The first (often the only) part of a patch's engraving."""
    parts = engraving_parts_of(patch)
    return parts[0] if parts else None


def engravings_of(sliceform):
    """The engraving children of a sliceform, by patch and part."""
    return [e for patch in patches_of(sliceform) for e in engraving_parts_of(patch)]


def _sheet_engravings(sliceform):
    """Engravings of a whole sheet, as documents made before engravings per patch hold."""
    return [o for o in sliceform.InList if _proxy_type(o) == "SliceformEngraving" and getattr(o, "Sliceform", None) == sliceform]


def views_of(obj):
    """The TechDraw views that show obj (a sheet patch or an engraving)."""
    return [o for o in obj.InList if o.TypeId == "TechDraw::DrawViewPart"]


def patch_views(page):
    """The views of a page that show patches (not their engravings)."""
    return [v for v in page.Views if v.Source and _proxy_type(v.Source[0]) == "SliceformSheetPatch"]


def engraving_views(page):
    """The views of a page that show engravings."""
    return [v for v in page.Views if v.Source and _proxy_type(v.Source[0]) == "SliceformEngraving"]


def _drawn_in_order(page):
    """Whether the page draws every patch view before every engraving view: each patch
    view's white face would hide the labels of an engraving drawn before it."""
    kinds = [_proxy_type(v.Source[0]) if v.Source else None for v in page.Views]
    engraved = [k == "SliceformEngraving" for k in kinds]
    return engraved == sorted(engraved)


def owned_objects(sliceform):
    """Everything the sliceform made, in an order that can be removed one by one: views,
    templates and pages first, then engravings, sheet patches, then patches."""
    out = []
    for page in pages_of(sliceform):
        out.extend(v for v in page.Views)
        template = page.Template
        if template is not None and not isinstance(template, str):
            out.append(template)
        out.append(page)
    for engraving in _sheet_engravings(sliceform):
        out.extend(v for v in views_of(engraving) if v not in out)
        out.append(engraving)
    patches = patches_of(sliceform)
    for patch in patches:
        for drawing in engraving_parts_of(patch) + [sheet_patch_of(patch)]:
            if drawing is not None:
                out.extend(v for v in views_of(drawing) if v not in out)
                out.append(drawing)
    out.extend(patches)
    return out


# ---------------------------------------------------------------------------------------------
# The children's features


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
        if not is_sliceform(obj.Sliceform):
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
        obj.Shape = patch_shape(patches[obj.Index])
        self.built = built


def _on_sheet(shapes, sheets):
    """shapes and two vertices at the sheet's corners, so that the compound's box is the
    sheet (TechDraw centres a view on its shape's box: the view then sits at the sheet's
    centre and the page shows the sheet at 1:1)."""
    corners = [Part.Vertex(0, 0, 0), Part.Vertex(sheets["width"], sheets["height"], 0)]
    return Part.makeCompound(shapes + corners)


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
        if not is_sliceform(sliceform):
            raise ValueError(QT_TRANSLATE_NOOP("Sliceform", "this drawing's patch or sliceform was deleted"))
        patches = sliceform.Proxy.flat_patches(sliceform)
        drawing = sliceform.Proxy.sheet_drawings(sliceform).get(patches[patch.Index]["id"]) if patch.Index < len(patches) else None
        if drawing is None:
            return  # left over from a larger design until the sync that follows removes it
        built = (sliceform.Proxy.key, patch.Index)
        if getattr(self, "built", None) == built and not obj.Shape.isNull():
            return
        obj.Shape = _on_sheet(geometry.patch_cuts(drawing), sliceform.Proxy.sheets(sliceform))
        self.built = built


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
        if not is_sliceform(sliceform):
            raise ValueError(QT_TRANSLATE_NOOP("Sliceform", "this engraving's patch or sliceform was deleted"))
        patches = sliceform.Proxy.flat_patches(sliceform)
        drawing = sliceform.Proxy.sheet_drawings(sliceform).get(patches[patch.Index]["id"]) if patch.Index < len(patches) else None
        parts = geometry.engraving_parts(drawing) if drawing is not None else []
        if obj.EngravingPart >= len(parts):
            return  # left over from a larger design until the sync that follows removes it
        built = (sliceform.Proxy.key, patch.Index, obj.EngravingPart, geometry.ENGRAVING_VIEW_EDGES)
        if getattr(self, "built", None) == built and not obj.Shape.isNull():
            return
        obj.Shape = _on_sheet(geometry.stroke_shapes(parts[obj.EngravingPart]), sliceform.Proxy.sheets(sliceform))
        self.built = built


def patch_shape(patch):
    """The patch's face (outline with its slots and holes) placed on its plane."""
    wires = []
    for loop in patch["loops"]:
        edges = [c.toShape() for c in geometry.loop_curves(loop, patch["exact"])]
        wires.append(Part.Wire(Part.__sortEdges__(edges)) if len(edges) > 1 else Part.Wire(edges))
    try:
        shape = Part.makeFace(wires, "Part::FaceMakerBullseye")
    except Part.OCCError:
        shape = Part.makeCompound(wires)  # still shows the outline
    shape.Placement = geometry.plane_placement(patch)
    return shape


# ---------------------------------------------------------------------------------------------
# Making and removing children


def _new_patch(doc, sliceform, index):
    obj = doc.addObject("Part::Part2DObjectPython", "{}_Patch{:03d}".format(sliceform.Name, index + 1))
    Patch(obj)
    obj.Sliceform = sliceform
    obj.Index = index
    if FreeCAD.GuiUp:
        from sliceform_gui import view_provider

        view_provider.ViewProviderPatch(obj.ViewObject)
        obj.ViewObject.Visibility = False
    return obj


def _new_sheet_patch(doc, patch):
    obj = doc.addObject("Part::FeaturePython", patch.Name + "_Sheet")
    SheetPatch(obj)
    obj.Patch = patch
    if FreeCAD.GuiUp:
        from sliceform_gui import view_provider

        view_provider.ViewProviderSheetPatch(obj.ViewObject)
        obj.ViewObject.Visibility = False
    return obj


def _new_page(doc, sliceform, index):
    page = doc.addObject("TechDraw::DrawPage", "{}_Sheet{:02d}".format(sliceform.Name, index + 1))
    page.addProperty("App::PropertyLink", "Sliceform", "Sliceform",
                     QT_TRANSLATE_NOOP("App::Property", "The sliceform whose sheet this page shows"))
    page.addProperty("App::PropertyInteger", "SheetIndex", "Sliceform",
                     QT_TRANSLATE_NOOP("App::Property", "Which sheet of the layout"))
    page.addProperty("App::PropertyString", "Sheet", "Sliceform",
                     QT_TRANSLATE_NOOP("App::Property", "The sheet's size and margin"))
    for name in ("Sliceform", "SheetIndex", "Sheet"):
        page.setEditorMode(name, 1)
    page.Sliceform = sliceform
    page.SheetIndex = index
    page.Template = doc.addObject("TechDraw::DrawSVGTemplate", "{}_Template{:02d}".format(sliceform.Name, index + 1))
    if FreeCAD.GuiUp:
        if hasattr(page.ViewObject, "ShowFrames"):
            page.ViewObject.ShowFrames = False  # a sheet to cut, not a drawing: no frames or labels
        # Closed until the user opens it: TechDraw opens a visible page again on reopening.
        page.ViewObject.Visibility = False
    return page


def _new_engraving(doc, patch, part):
    obj = doc.addObject("Part::FeaturePython", patch.Name + "_Engraving" + ("" if part == 0 else str(part + 1)))
    Engraving(obj)
    obj.Patch = patch
    obj.EngravingPart = part
    if FreeCAD.GuiUp:
        from sliceform_gui import view_provider

        view_provider.ViewProviderSheetPatch(obj.ViewObject)
        obj.ViewObject.Visibility = False
    return obj


def _engrave_view_name(patch, part):
    """..._Engrave: TechDraw's DXF writes each view on a layer named after it, so a laser's
    software can map every layer ending so to engraving."""
    return patch.Name + ("" if part == 0 else "_{}".format(part + 1)) + "_Engrave"


def _centre(view, sheets):
    """Puts the view at the sheet's centre (set only when it is not there: a set marks it
    for recompute)."""
    centre = (sheets["width"] / 2, sheets["height"] / 2)
    if (round(view.X.Value, 6), round(view.Y.Value, 6)) != tuple(round(c, 6) for c in centre):
        view.X, view.Y = centre


def _new_view(doc, page, source, name):
    view = doc.addObject("TechDraw::DrawViewPart", name)
    page.addView(view)
    view.Source = [source]
    view.Direction, view.XDirection = V(0, 0, 1), V(1, 0, 0)
    view.ScaleType, view.Scale = "Custom", 1.0
    return view


def settle_views(seconds=60):
    """Lets every TechDraw view finish what its threads are doing. FreeCAD 1.0 computes a
    view's hidden lines, then its faces, in Qt's global thread pool and finishes the job in
    the view when the result arrives through the event loop; a view removed meanwhile gets
    that call with no name in the document and throws (std::logic_error through the event
    loop: headless, a crashed interpreter). FreeCAD 0.20 computes views in the recompute,
    and this returns at once. User input is not processed while waiting."""
    try:
        from PySide import QtCore
    except ImportError:
        return
    app = QtCore.QCoreApplication.instance()
    if app is None:
        return
    pool = QtCore.QThreadPool.globalInstance()
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        pool.waitForDone(100)
        # A finished hidden-line pass starts face finding: loop until both are delivered.
        app.processEvents(QtCore.QEventLoop.ExcludeUserInputEvents)
        if pool.activeThreadCount() == 0:
            app.processEvents(QtCore.QEventLoop.ExcludeUserInputEvents)
            if pool.activeThreadCount() == 0:
                return


def remove_objects(doc, objects):
    if any(o.TypeId == "TechDraw::DrawViewPart" or o.TypeId == "TechDraw::DrawPage" for o in objects):
        settle_views()
    names = [o.Name for o in objects]
    for name in names:
        obj = doc.getObject(name)
        if obj is None:
            continue
        if obj.TypeId == "TechDraw::DrawViewPart":
            for page in [o for o in obj.InList if o.TypeId == "TechDraw::DrawPage"]:
                page.removeView(obj)
        elif obj.TypeId == "TechDraw::DrawPage":
            # Emptied first, its template too: FreeCAD 1.0 removes a page's views itself when
            # the page goes (DrawPage::unsetupObject) and crashed on views already removed.
            page_views = list(obj.Views)
            obj.Views = []
            template = obj.Template
            if template is not None and not isinstance(template, str):
                obj.Template = None
                if template not in objects:
                    page_views.append(template)
            remove_objects(doc, page_views)
        doc.removeObject(name)


def remove_children(sliceform):
    """Removes everything the sliceform made."""
    remove_objects(sliceform.Document, owned_objects(sliceform))


def template_for(sheets):
    """A blank SVG template of the sheet's size with the margin drawn, written once into
    FreeCAD's user data folder (TechDraw copies it into the document)."""
    w, h, m = sheets["width"], sheets["height"], sheets["margin"]
    folder = os.path.join(FreeCAD.getUserAppDataDir(), "Sliceform", "templates")
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, "Sheet_{:g}x{:g}_m{:g}.svg".format(w, h, m))
    if not os.path.isfile(path):
        svg = (
            '<?xml version="1.0" encoding="UTF-8"?>\n'
            '<svg xmlns="http://www.w3.org/2000/svg" xmlns:freecad="http://www.freecadweb.org/wiki/index.php?title=Svg_Namespace" '
            'width="{w:g}mm" height="{h:g}mm" viewBox="0 0 {w:g} {h:g}">\n'
            '  <rect x="{m:g}" y="{m:g}" width="{iw:g}" height="{ih:g}" fill="none" stroke="#bbbbbb" '
            'stroke-width="0.2" stroke-dasharray="2,2"/>\n</svg>\n'
        ).format(w=w, h=h, m=m, iw=w - 2 * m, ih=h - 2 * m)
        tmp = path + ".tmp"
        with open(tmp, "w") as f:
            f.write(svg)
        os.replace(tmp, path)
    return path


# ---------------------------------------------------------------------------------------------
# sync: the children follow the design


def _sheet_text(sheets):
    return "{:g} x {:g} mm, margin {:g} mm".format(sheets["width"], sheets["height"], sheets["margin"])


def _page_label(sliceform, index):
    return "{} sheet {}".format(sliceform.Label, index + 1)


def wanted(sliceform):
    """What the children should be for the sliceform's design: the patch ids in order, the
    sheet of each, the pages (label and sheet size) and where the views sit; None when there
    is no design to show."""
    proxy = sliceform.Proxy
    # Right after its recompute, a valid feature's design is the one its properties ask for.
    if getattr(proxy, "design", None) is None or not sliceform.isValid() or "Touched" in sliceform.State:
        return None
    ids = [p["id"] for p in proxy.flat_patches(sliceform)]
    sheets = proxy.sheets(sliceform)
    sheet_of = {}
    for s, patches in enumerate(sheets["sheets"]):
        for p in patches:
            sheet_of[p["id"]] = s
    pages = [(_page_label(sliceform, i), _sheet_text(sheets), True) for i in range(len(sheets["sheets"]))]
    centre = (round(sheets["width"] / 2, 6), round(sheets["height"] / 2, 6))
    drawings = proxy.sheet_drawings(sliceform)
    parts = [len(geometry.engraving_parts(drawings[i])) if i in drawings else 1 for i in ids]
    return ids, [sheet_of.get(i, -1) for i in ids], pages, [centre] * len(ids), parts


def shown(sliceform):
    """What the children show now, in wanted()'s terms."""
    patches = patches_of(sliceform)
    ids = [p.PatchId for p in patches]
    sheets, centres, parts = [], [], []
    page_of_view = {}
    pages = pages_of(sliceform)
    for page in pages:
        for view in page.Views:
            page_of_view[view.Name] = page.SheetIndex
    for patch in patches:
        # A patch shows on a sheet when its drawing and each part of its engraving have one
        # view, all on that sheet's page, all centred on it.
        engraving = engraving_parts_of(patch)
        parts.append(len(engraving) if [e.EngravingPart for e in engraving] == list(range(len(engraving))) else -1)
        drawings = [sheet_patch_of(patch)] + (engraving or [None])
        views = [views_of(d) if d is not None else [] for d in drawings]
        where = {page_of_view.get(v[0].Name, -1) for v in views if len(v) == 1}
        at = {(round(v[0].X.Value, 6), round(v[0].Y.Value, 6)) for v in views if v}
        sheets.append(where.pop() if all(len(v) == 1 for v in views) and len(where) == 1 else -2)
        centres.append(at.pop() if len(at) == 1 else None)
    pages = [(p.Label, getattr(p, "Sheet", ""), _drawn_in_order(p)) for p in pages]
    if _sheet_engravings(sliceform):
        pages.append(None)  # an older document's engravings are still there
    return ids, sheets, pages, centres, parts


def sync(sliceform, recompute=True):
    """Makes the children match the design: adds or removes patches, sheet patches, views and
    pages when the counts change, moves views between pages, sets the labels to the patch
    ids, and recomputes what it changed. Does nothing when they match already. Returns
    True when it changed the document."""
    want = wanted(sliceform)
    if want is None or want == shown(sliceform):
        return False
    ids, sheet_index, page_list, _centres, part_counts = want
    sheet_count = len(page_list)
    doc = sliceform.Document
    if _observer is not None:
        _observer.pending.discard((doc.Name, sliceform.Name))
    proxy = sliceform.Proxy
    sheets = proxy.sheets(sliceform)
    # An older document's children (the feature linked them) give way to the new ones.
    old = [doc.getObject(n) for n in getattr(proxy, "old_children", [])]
    remove_objects(doc, [o for o in old if o is not None])
    proxy.old_children = []

    # Patches and their sheet patches, by index.
    patches = patches_of(sliceform)
    extra = patches[len(ids):]
    for patch in extra:
        for drawing in engraving_parts_of(patch) + [sheet_patch_of(patch)]:
            if drawing is not None:
                remove_objects(doc, views_of(drawing) + [drawing])
    remove_objects(doc, extra)
    patches = patches[: len(ids)]
    while len(patches) < len(ids):
        patches.append(_new_patch(doc, sliceform, len(patches)))

    # Pages, by sheet.
    pages = pages_of(sliceform)
    for page in pages[sheet_count:]:
        template = page.Template
        remove_objects(doc, [page] + ([template] if template is not None and not isinstance(template, str) else []))
    pages = pages[:sheet_count]
    while len(pages) < sheet_count:
        pages.append(_new_page(doc, sliceform, len(pages)))
    for i, page in enumerate(pages):
        if page.Label != _page_label(sliceform, i):
            page.Label = _page_label(sliceform, i)
        if page.Sheet != _sheet_text(sheets):  # TechDraw keeps its own copy of the file
            page.Template.Template = template_for(sheets)
            page.Sheet = _sheet_text(sheets)

    # A whole sheet's engravings, as earlier documents have them, give way to a patch's.
    for engraving in _sheet_engravings(sliceform):
        remove_objects(doc, views_of(engraving) + [engraving])

    def view_on(page, source, name):
        """The one view of source, on page (made or moved there)."""
        found = views_of(source)
        remove_objects(doc, found[1:])
        view = found[0] if found else _new_view(doc, page, source, name)
        owner = [p for p in pages if view in p.Views]
        if owner != [page]:
            for other in owner:
                other.removeView(view)
            page.addView(view)
        _centre(view, sheets)
        return view

    views, engraved = [], []
    for patch, patch_id, s, count in zip(patches, ids, sheet_index, part_counts):
        sheet_patch = sheet_patch_of(patch) or _new_sheet_patch(doc, patch)
        views.append((patch, sheet_patch, view_on(pages[s], sheet_patch, patch.Name + "_View")))
        parts = engraving_parts_of(patch)
        for engraving in parts[count:]:
            remove_objects(doc, views_of(engraving) + [engraving])
        parts = parts[:count]
        while len(parts) < count:
            parts.append(_new_engraving(doc, patch, len(parts)))
        for k, engraving in enumerate(parts):
            if engraving.EngravingPart != k:
                engraving.EngravingPart = k
            engraved.append((engraving, view_on(pages[s], engraving, _engrave_view_name(patch, k))))
    # Engravings after every patch view of their page: a page draws its views in this
    # order, and each patch view's white face would hide the labels of one drawn before it.
    for page in pages:
        if not _drawn_in_order(page):
            for view in engraving_views(page):
                page.removeView(view)
                page.addView(view)

    # Labels go through a temporary name first: FreeCAD keeps labels unique, and a label
    # taken by a sibling for a moment would come out renumbered ("U002" for U1).
    labels = []
    for (patch, sheet_patch, view), patch_id, s in zip(views, ids, sheet_index):
        if patch.PatchId != patch_id:
            patch.PatchId = patch_id
        labels += [
            (patch, "{} patch {}".format(sliceform.Label, patch_id)),
            (sheet_patch, "{} on sheet {}".format(patch_id, s + 1)),
            (view, patch_id),
        ]
    sheet_of_patch = {patch.Name: (patch_id, s) for patch, patch_id, s in zip(patches, ids, sheet_index)}
    for engraving, view in engraved:
        patch_id, s = sheet_of_patch[engraving.Patch.Name]
        part = "" if engraving.EngravingPart == 0 else " {}".format(engraving.EngravingPart + 1)
        labels += [(engraving, "{} engraving{} on sheet {}".format(patch_id, part, s + 1)),
                   (view, "{} engraving{}".format(patch_id, part))]
    labels = [(obj, label) for obj, label in labels if obj.Label != label]
    for obj, _label in labels:
        obj.Label = obj.Name + "_"
    for obj, label in labels:
        obj.Label = label

    # The new and changed children are built now, by a recompute of the document (none
    # can run inside another: then each is built alone and stays marked for recompute).
    engraved = [o for pair in engraved for o in pair]
    changed = [p.Template for p in pages] + [o for v in views for o in v] + engraved + pages
    if recompute:
        doc.recompute([o for o in changed if "Touched" in o.State])
    else:
        order = [p.Template for p in pages] + [v[i] for i in range(3) for v in views] + engraved + pages
        for obj in order:
            if "Touched" in obj.State:
                obj.recompute()
    # The tree asks a parent for its children when the parent changes; these link to it,
    # so it has not. ChildCount is an output: setting it marks nothing for recompute.
    sliceform.ChildCount = len(patches) + len(pages) + len(engraved) // 2  # and engravings
    return True


# ---------------------------------------------------------------------------------------------
# The document recompute: a source edit that changes the count is followed by a sync,
# inside the transaction of that edit.


class _Observer:
    """Follows every document recompute: a sliceform recomputed inside a transaction (a
    property edited in the property editor, a command) gets its children synced just
    before that transaction closes, so what changes is part of the same Undo step. Outside
    any transaction (a script with Undo off) they are synced right after the recompute."""

    def __init__(self):
        self.busy = False
        self.pending = set()  # (document, sliceform) names recomputed and not synced yet

    def slotRecomputedObject(self, obj):
        if _proxy_type(obj) == "Sliceform":
            self.pending.add((obj.Document.Name, obj.Name))

    def slotRecomputedDocument(self, doc):
        from sliceform_app import feature

        feature.restore_traceback()
        if getattr(doc, "HasPendingTransaction", False):
            return  # synced before the transaction closes
        # No transaction: nothing to keep in one Undo step. No recompute can run inside
        # this one: the GUI syncs as soon as it is over; without it, the new children are
        # built one by one now and stay marked for the next recompute.
        if FreeCAD.GuiUp:
            from PySide import QtCore

            name = doc.Name
            QtCore.QTimer.singleShot(0, lambda: self._sync(lambda d: d == name, recompute=True))
        else:
            self._sync(lambda d: d == doc.Name, recompute=False)

    def slotBeforeCloseTransaction(self, abort):
        if abort:
            self.pending.clear()  # the document goes back to what it was
        else:
            self._sync(lambda d: True, recompute=True)

    def _sync(self, which, recompute):
        if self.busy:
            return
        names = [(d, n) for d, n in self.pending if which(d)]
        self.pending.difference_update(names)
        self.busy = True
        try:
            for d, n in names:
                doc = FreeCAD.listDocuments().get(d)
                obj = doc.getObject(n) if doc is not None else None
                if obj is None or getattr(doc, "Transacting", False) or not is_sliceform(obj):
                    continue
                try:
                    sync(obj, recompute)
                except Exception as e:  # never break the user's edit
                    FreeCAD.Console.PrintError("Sliceform: {}\n".format(e))
        finally:
            self.busy = False


_observer = None


class held:
    """with held(): doc.recompute(); sync(obj) -- the caller syncs, the observer waits."""

    def __enter__(self):
        self.was = _observer.busy if _observer else False
        self.pending = set(_observer.pending) if _observer else set()
        if _observer:
            _observer.busy = True

    def __exit__(self, *exc):
        if _observer:
            _observer.busy = self.was
            _observer.pending = self.pending


def install_observer():
    global _observer
    if _observer is None:
        _observer = _Observer()
        FreeCAD.addDocumentObserver(_observer)
