# SPDX-License-Identifier: LGPL-2.1-or-later
"""The children follow the design: sync() compares what the design wants (wanted()) with
what the children show (shown()) and makes, removes, moves, relabels and recomputes only
what differs."""

from sliceform_app import geometry, lookup, making, observer


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
    patches = lookup.patches_of(sliceform)
    ids = [p.PatchId for p in patches]
    sheets, centres, parts = [], [], []
    page_of_view = {}
    pages = lookup.pages_of(sliceform)
    for page in pages:
        for view in page.Views:
            page_of_view[view.Name] = page.SheetIndex
    for patch in patches:
        # A patch shows on a sheet when its drawing and each part of its engraving have one
        # view, all on that sheet's page, all centred on it.
        engraving = lookup.engraving_parts_of(patch)
        parts.append(len(engraving) if [e.EngravingPart for e in engraving] == list(range(len(engraving))) else -1)
        drawings = [lookup.sheet_patch_of(patch)] + (engraving or [None])
        views = [lookup.views_of(d) if d is not None else [] for d in drawings]
        where = {page_of_view.get(v[0].Name, -1) for v in views if len(v) == 1}
        at = {(round(v[0].X.Value, 6), round(v[0].Y.Value, 6)) for v in views if v}
        sheets.append(where.pop() if all(len(v) == 1 for v in views) and len(where) == 1 else -2)
        centres.append(at.pop() if len(at) == 1 else None)
    pages = [(p.Label, getattr(p, "Sheet", ""), lookup.drawn_in_order(p)) for p in pages]
    if lookup.sheet_engravings(sliceform):
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
    observer.synced(doc.Name, sliceform.Name)
    proxy = sliceform.Proxy
    sheets = proxy.sheets(sliceform)
    # An older document's children (the feature linked them) give way to the new ones.
    old = [doc.getObject(n) for n in getattr(proxy, "old_children", [])]
    making.remove_objects(doc, [o for o in old if o is not None])
    proxy.old_children = []

    # Patches and their sheet patches, by index.
    patches = lookup.patches_of(sliceform)
    extra = patches[len(ids):]
    for patch in extra:
        for drawing in lookup.engraving_parts_of(patch) + [lookup.sheet_patch_of(patch)]:
            if drawing is not None:
                making.remove_objects(doc, lookup.views_of(drawing) + [drawing])
    making.remove_objects(doc, extra)
    patches = patches[: len(ids)]
    while len(patches) < len(ids):
        patches.append(making.new_patch(doc, sliceform, len(patches)))

    # Pages, by sheet. The pages of sheets the design no longer has go once the views of
    # the patches still there have moved off them (below): removing a page removes its views,
    # and a view that may still be drawing is removed only after every view settled
    # (settling.py); a view moved keeps drawing where it is (fandisk, a Slices edit that
    # drops a sheet: 0.9 s of FreeCAD 1.0's waiting, and views made again for the patches
    # on it).
    pages = lookup.pages_of(sliceform)
    surplus = pages[sheet_count:]
    pages = pages[:sheet_count]
    while len(pages) < sheet_count:
        pages.append(making.new_page(doc, sliceform, len(pages)))
    for i, page in enumerate(pages):
        if page.Label != _page_label(sliceform, i):
            page.Label = _page_label(sliceform, i)
        if page.Sheet != _sheet_text(sheets):  # TechDraw keeps its own copy of the file
            page.Template.Template = making.template_for(sheets)
            page.Sheet = _sheet_text(sheets)

    # A whole sheet's engravings, as earlier documents have them, give way to a patch's.
    for engraving in lookup.sheet_engravings(sliceform):
        making.remove_objects(doc, lookup.views_of(engraving) + [engraving])

    def view_on(page, source, name):
        """The one view of source, on page (made or moved there)."""
        found = lookup.views_of(source)
        making.remove_objects(doc, found[1:])
        view = found[0] if found else making.new_view(doc, page, source, name)
        owner = [p for p in pages + surplus if view in p.Views]
        if owner != [page]:
            for other in owner:
                other.removeView(view)
            page.addView(view)
        making.centre_on_sheet(view, sheets)
        return view

    views, engraved = [], []
    for patch, patch_id, s, count in zip(patches, ids, sheet_index, part_counts):
        sheet_patch = lookup.sheet_patch_of(patch) or making.new_sheet_patch(doc, patch)
        views.append((patch, sheet_patch, view_on(pages[s], sheet_patch, patch.Name + "_View")))
        parts = lookup.engraving_parts_of(patch)
        for engraving in parts[count:]:
            making.remove_objects(doc, lookup.views_of(engraving) + [engraving])
        parts = parts[:count]
        while len(parts) < count:
            parts.append(making.new_engraving(doc, patch, len(parts)))
        for k, engraving in enumerate(parts):
            if engraving.EngravingPart != k:
                engraving.EngravingPart = k
            engraved.append((engraving, view_on(pages[s], engraving, making.engrave_view_name(patch, k))))
    for page in surplus:
        template = page.Template
        making.remove_objects(doc, [page] + ([template] if template is not None and not isinstance(template, str) else []))

    # Engravings after every patch view of their page: a page draws its views in this
    # order, and each patch view's white face would hide the labels of one drawn before it.
    for page in pages:
        if not lookup.drawn_in_order(page):
            for view in lookup.engraving_views(page):
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
