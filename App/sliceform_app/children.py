# SPDX-License-Identifier: LGPL-2.1-or-later
"""The Sliceform feature's children, regenerated in place on every recompute: one sketch per
patch (in a group) and one TechDraw page per sheet. Objects are reused by position, so
their names stay stable while the patch and sheet counts do; extra ones are removed."""
import os

import FreeCAD

from sliceform_app import geometry

V = FreeCAD.Vector


def _reuse(doc, existing, count, make):
    """`count` objects: the existing ones first, new ones from make(i) after; the rest are
    removed from the document."""
    kept = [o for o in existing if o is not None and o.Document == doc][:count]
    for extra in [o for o in existing if o is not None and o not in kept]:
        if extra.Document == doc:
            _remove(doc, extra)
    while len(kept) < count:
        kept.append(make(len(kept)))
    return kept


def _remove(doc, obj):
    """Removes a child and what only it uses: a page's views and template, a view's source.
    A page is emptied first and removed last: FreeCAD 1.0 removes a page's views itself when
    the page goes, and crashed (in DrawPage::unsetupObject) on views already removed in the
    same recompute."""
    if obj.TypeId == "TechDraw::DrawPage":
        for view in list(obj.Views or []):
            obj.removeView(view)
            if view.Document == doc:
                _remove(doc, view)
        template = obj.Template
        if template is not None and not isinstance(template, str):
            obj.Template = None
            if template.Document == doc:
                doc.removeObject(template.Name)
        doc.removeObject(obj.Name)
        return
    owned = list(obj.Source) if obj.TypeId == "TechDraw::DrawViewPart" else []
    doc.removeObject(obj.Name)  # first, so no view recomputes without its source
    for child in owned:
        if child.Document == doc:
            _remove(doc, child)


def _group(feature, prop, suffix, what):
    """The feature's group held in property `prop`, made if missing."""
    doc = feature.Document
    group = getattr(feature, prop)
    if group is None or group.Document != doc:
        group = doc.addObject("App::DocumentObjectGroup", feature.Name + suffix)
        setattr(feature, prop, group)
    group.Label = "{} {}".format(feature.Label, what)
    group.purgeTouched()
    return group


def update_sketches(feature, patches):
    """One Sketcher::SketchObject per patch on its plane: the exact outline and slots."""
    doc = feature.Document
    group = _group(feature, "PatchGroup", "_Patches", "patches")

    def make(i):
        sketch = doc.addObject("Sketcher::SketchObject", "{}_Patch{:03d}".format(feature.Name, i))
        group.addObject(sketch)
        return sketch

    sketches = _reuse(doc, list(feature.PatchSketches), len(patches), make)
    for sketch, patch in zip(sketches, patches):
        sketch.deleteAllGeometry()
        curves = [c for loop in patch["loops"] for c in geometry.loop_curves(loop, patch["exact"])]
        sketch.addGeometry(curves, False)
        sketch.Placement = geometry.plane_placement(patch)
        sketch.Label = "{} {}".format(feature.Label, patch["id"])
        sketch.Visibility = False
        # Solved and built now, so the next document recompute has nothing left to do.
        sketch.recompute()
        sketch.purgeTouched()
    feature.PatchSketches = sketches
    return sketches


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


def _make_page(doc, feature, i):
    page = doc.addObject("TechDraw::DrawPage", "{}_Sheet{:02d}".format(feature.Name, i + 1))
    page.Template = doc.addObject("TechDraw::DrawSVGTemplate", "{}_Template{:02d}".format(feature.Name, i + 1))
    return page


def _sheet_group(feature):
    return _group(feature, "SheetGroup", "_SheetShapes", "sheet geometry")


def _update_views(feature, page, patches):
    """One view per patch (TechDraw's hidden-line pass grows much faster than the edge
    count: 17 views of a sheet take 0.5 s, one view of it 8 s), each showing a hidden
    Part::Feature with the patch's cut lines and labels in sheet millimetres."""
    doc = feature.Document
    group = _sheet_group(feature)

    def make(i):
        source = doc.addObject("Part::Feature", "{}_Part".format(page.Name))
        source.Visibility = False
        group.addObject(source)
        view = doc.addObject("TechDraw::DrawViewPart", "{}_View".format(page.Name))
        page.addView(view)
        view.Source = [source]
        return view

    views = _reuse(doc, list(page.Views), len(patches), make)
    for view, patch in zip(views, patches):
        shape = geometry.patch_drawing(patch)
        source = view.Source[0]
        source.Shape = shape
        source.Label = "{} {}".format(page.Label, patch["id"])
        view.Label = "{} {}".format(page.Label, patch["id"])
        view.Direction, view.XDirection = V(0, 0, 1), V(1, 0, 0)
        view.ScaleType, view.Scale = "Custom", 1.0
        # TechDraw centres a view on its shape's bounding box: put that centre where it is
        # on the sheet, and the page shows the sheet at 1:1.
        box = shape.BoundBox
        view.X, view.Y = box.Center.x, box.Center.y
        view.recompute()
        view.purgeTouched()
        source.purgeTouched()


def update_pages(feature, sheets):
    """One TechDraw page per sheet: the nested layout at 1:1 on a template of the sheet's
    size, patch by patch, labels included."""
    doc = feature.Document
    pages = _reuse(doc, list(feature.Pages), len(sheets["sheets"]), lambda i: _make_page(doc, feature, i))
    template = template_for(sheets)
    for i, (page, patches) in enumerate(zip(pages, sheets["sheets"])):
        page.Label = "{} sheet {}".format(feature.Label, i + 1)
        if page.Template.Template != template:
            page.Template.Template = template
        page.Template.recompute()
        page.Template.purgeTouched()
        _update_views(feature, page, patches)
        if FreeCAD.GuiUp and hasattr(page.ViewObject, "ShowFrames"):
            page.ViewObject.ShowFrames = False  # a sheet to cut, not a drawing: no view frames or labels
        page.recompute()
        page.purgeTouched()
    feature.Pages = pages
    return pages
