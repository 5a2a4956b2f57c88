# SPDX-License-Identifier: LGPL-2.1-or-later
"""Which objects are whose: a sliceform's children (children.py), its TechDraw pages and
their views, found from the links that point to the sliceform; the sliceform lists none of
them, as a TechDraw source does not list its views."""


def is_sliceform(obj):
    from sliceform_app import feature

    return obj is not None and isinstance(getattr(obj, "Proxy", None), feature.Sliceform)


def proxy_type(obj):
    return getattr(getattr(obj, "Proxy", None), "Type", None)


def patches_of(sliceform):
    """The patch children of a sliceform, by index."""
    found = [o for o in sliceform.InList if proxy_type(o) == "SliceformPatch" and o.Sliceform == sliceform]
    return sorted(found, key=lambda o: o.Index)


def sheet_patch_of(patch):
    for o in patch.InList:
        if proxy_type(o) == "SliceformSheetPatch" and o.Patch == patch:
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
    found = [o for o in patch.InList if proxy_type(o) == "SliceformEngraving" and getattr(o, "Patch", None) == patch]
    return sorted(found, key=lambda o: getattr(o, "EngravingPart", 0))


def engravings_of(sliceform):
    """The engraving children of a sliceform, by patch and part."""
    return [e for patch in patches_of(sliceform) for e in engraving_parts_of(patch)]


def sheet_engravings(sliceform):
    """Engravings of a whole sheet, as documents made before engravings per patch hold."""
    return [o for o in sliceform.InList if proxy_type(o) == "SliceformEngraving" and getattr(o, "Sliceform", None) == sliceform]


def views_of(obj):
    """The TechDraw views that show obj (a sheet patch or an engraving)."""
    return [o for o in obj.InList if o.TypeId == "TechDraw::DrawViewPart"]


def patch_views(page):
    """The views of a page that show patches (not their engravings)."""
    return [v for v in page.Views if v.Source and proxy_type(v.Source[0]) == "SliceformSheetPatch"]


def engraving_views(page):
    """The views of a page that show engravings."""
    return [v for v in page.Views if v.Source and proxy_type(v.Source[0]) == "SliceformEngraving"]


def drawn_in_order(page):
    """Whether the page draws every patch view before every engraving view: each patch
    view's white face would hide the labels of an engraving drawn before it."""
    kinds = [proxy_type(v.Source[0]) if v.Source else None for v in page.Views]
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
    for engraving in sheet_engravings(sliceform):
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
