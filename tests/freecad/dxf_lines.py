# SPDX-License-Identifier: LGPL-2.1-or-later
"""TechDraw's DXF of a sliceform's page against the sheet's own drawing (Design.sheets), for
the headless test and the GUI test (gui_children.py)."""
import os
import re
import tempfile


def lines_away(sliceform, sheet=0):
    """The starts of the LINEs in TechDraw's DXF of page `sheet` that lie at no corner of a
    cut or a stroke of the sheet's drawing, to 2 µm (the DXF's digits), and the count of
    LINEs: a laser cuts and engraves what the core drew, where it drew it, when the first
    list is empty."""
    import TechDraw

    from sliceform_app import lookup

    page = lookup.pages_of(sliceform)[sheet]
    path = os.path.join(tempfile.mkdtemp(), "sheet.dxf")
    TechDraw.writeDXFPage(page, path)
    corners = set()
    for d in sliceform.Proxy.sheets(sliceform)["sheets"][sheet]:
        for stroke in d["engrave"]:
            corners.update((round(x, 3), round(y, 3)) for x, y in stroke)
        for loop in d["cut"]:
            for e in loop:
                corners.update((round(e[k][0], 3), round(e[k][1], 3)) for k in ("a", "b") if k in e)
    with open(path) as f:
        text = f.read()
    starts = [(float(x), float(y)) for x, y in re.findall(r"\nLINE\n(?:.*\n)*? 10\n([-\d.eE+]+)\n 20\n([-\d.eE+]+)\n", text)]
    away = [(x, y) for x, y in starts
            if min(abs(round(x, 3) - cx) + abs(round(y, 3) - cy) for cx, cy in corners) >= 0.002]
    return away, len(starts)
