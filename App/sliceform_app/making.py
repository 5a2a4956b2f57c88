# SPDX-License-Identifier: LGPL-2.1-or-later
"""Making and removing a sliceform's children (children.py): patches, sheet patches,
engravings, TechDraw pages with their templates and views."""
import os

import FreeCAD

from sliceform_app import children, lookup, settling

V = FreeCAD.Vector
QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP


def _child(doc, kind, name, proxy, view, **links):
    """A child object: its proxy, its links set in the order given, and, in the GUI, its view
    provider, hidden (the sliceform shows the assembly)."""
    obj = doc.addObject(kind, name)
    proxy(obj)
    for prop, value in links.items():
        setattr(obj, prop, value)
    if FreeCAD.GuiUp:
        from sliceform_gui import view_provider

        getattr(view_provider, view)(obj.ViewObject)
        obj.ViewObject.Visibility = False
    return obj


def new_patch(doc, sliceform, index):
    name = "{}_Patch{:03d}".format(sliceform.Name, index + 1)
    return _child(doc, "Part::Part2DObjectPython", name, children.Patch, "ViewProviderPatch", Sliceform=sliceform,
                  Index=index)


def new_sheet_patch(doc, patch):
    return _child(doc, "Part::FeaturePython", patch.Name + "_Sheet", children.SheetPatch, "ViewProviderSheetPatch",
                  Patch=patch)


def new_page(doc, sliceform, index):
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


def new_engraving(doc, patch, part):
    name = patch.Name + "_Engraving" + ("" if part == 0 else str(part + 1))
    return _child(doc, "Part::FeaturePython", name, children.Engraving, "ViewProviderSheetPatch", Patch=patch,
                  EngravingPart=part)


def engrave_view_name(patch, part):
    """..._Engrave: TechDraw's DXF writes each view on a layer named after it, so a laser's
    software can map every layer ending so to engraving."""
    return patch.Name + ("" if part == 0 else "_{}".format(part + 1)) + "_Engrave"


def centre_on_sheet(view, sheets):
    """Puts the view at the sheet's centre (set only when it is not there: a set marks it
    for recompute)."""
    centre = (sheets["width"] / 2, sheets["height"] / 2)
    if (round(view.X.Value, 6), round(view.Y.Value, 6)) != tuple(round(c, 6) for c in centre):
        view.X, view.Y = centre


def new_view(doc, page, source, name):
    view = doc.addObject("TechDraw::DrawViewPart", name)
    page.addView(view)
    view.Source = [source]
    view.Direction, view.XDirection = V(0, 0, 1), V(1, 0, 0)
    view.ScaleType, view.Scale = "Custom", 1.0
    return view


def remove_objects(doc, objects):
    views = [o for o in objects if o.TypeId == "TechDraw::DrawViewPart"]
    views += [v for o in objects if o.TypeId == "TechDraw::DrawPage" for v in o.Views]
    if settling.may_be_drawing(views):
        settling.settle_views()
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
    remove_objects(sliceform.Document, lookup.owned_objects(sliceform))


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
