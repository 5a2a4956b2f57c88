# SPDX-License-Identifier: LGPL-2.1-or-later
"""End to end: `sliceform design MODEL -o DIR`, then the exported sheets are read back by
independent readers and held against report.json, in millimetres:

- the PDF has one page per sheet at the sheet's size, and pdftoppm renders every page;
- every patch's outer outline, placed as the report says, is found exactly once among the
  red (cut) paths of its sheet's SVG and among the CUT chains of its sheet's DXF, with the
  same width and height (within 0.03 mm);
- the DXF has layers CUT (red) and ENGRAVE (blue), mm units, $ACADVER, and keeps arcs as
  ARC/CIRCLE; every CUT chain closes, so no label stroke sits on CUT; every engraved mark
  lies inside a patch;
- no two patches overlap on a sheet, and all stay inside the margins.

Usage: export_check.py SLICEFORM MODEL [extra design options]
MODEL "torus" or "sphere" builds that solid as a BREP with FreeCAD's Part module first.
"""
import json
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import ezdxf
import ezdxf.bbox
import matplotlib.image
import numpy as np
from matplotlib.path import Path

TOL = 0.03  # mm: exact edges polygonised within 0.01 mm, plus cairo's 1/256 mm grid


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


SOLIDS = {  # built with FreeCAD's Part module; a sphere's sections are circles, kept as arcs
    "torus": "Part.makeTorus(40, 15)",
    "sphere": "Part.makeSphere(40)",
}


def make_solid(folder, name):
    # In a process of its own: FreeCAD's modules do not mix with matplotlib's in one.
    path = os.path.join(folder, name + ".brep")
    script = ("import sys; sys.path.append('/usr/lib/freecad-python3/lib'); import FreeCAD, Part; "
              f"{SOLIDS[name]}.exportBrep({path!r})")
    subprocess.run([sys.executable, "-c", script], check=True)
    return path


def placed(loop, placement):
    a = np.radians(placement["rotation_deg"])
    c, s = np.cos(a), np.sin(a)
    pts = np.asarray(loop, dtype=float)
    return np.column_stack(
        (c * pts[:, 0] - s * pts[:, 1] + placement["x_mm"], s * pts[:, 0] + c * pts[:, 1] + placement["y_mm"])
    )


def bbox(points):
    pts = np.asarray(points, dtype=float)
    return np.concatenate((pts.min(axis=0), pts.max(axis=0)))


def same_box(a, b):
    return bool(np.all(np.abs(np.asarray(a) - np.asarray(b)) <= TOL))


# --- SVG: cairo writes absolute M/L/C/Z paths; y runs down from the top of the sheet.
def svg_loops(path, height):
    root = ET.parse(path).getroot()
    ns = "{http://www.w3.org/2000/svg}"
    if not re.fullmatch(r"[0-9.]+mm", root.get("width", "")):
        fail(f"{path}: width is not in mm: {root.get('width')}")
    loops = {"cut": [], "engrave": []}
    for element in root.iter(ns + "path"):
        # The stroke colour: in the style attribute (cairo 1.16, Debian 12) or as its own
        # attribute, "rgb(100%, 0%, 0%)" (cairo 1.18, Debian 13).
        style = element.get("style", "")
        in_style = re.search(r"(?:^|;)\s*stroke\s*:\s*([^;]+)", style)
        stroke = (element.get("stroke") or (in_style.group(1) if in_style else "")).replace(" ", "")
        kind = {"rgb(100%,0%,0%)": "cut", "rgb(0%,0%,100%)": "engrave"}.get(stroke)
        if kind is None:
            fail(f"{path}: unexpected path stroke: {stroke!r} (style {style!r})")
        matrix = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0]
        if element.get("transform"):
            m = re.fullmatch(r"matrix\(([^)]*)\)", element.get("transform"))
            if not m:
                fail(f"{path}: unexpected transform {element.get('transform')}")
            matrix = [float(x) for x in m.group(1).replace(",", " ").split()]
        start = len(loops[kind])
        tokens = re.findall(r"[MLCZ]|-?[0-9.]+(?:e-?[0-9]+)?", element.get("d"))
        current, points, i = None, [], 0
        while i < len(tokens):
            t = tokens[i]
            if t == "M":
                if points:
                    loops[kind].append(points)
                current = (float(tokens[i + 1]), float(tokens[i + 2]))
                points, i = [current], i + 3
            elif t == "L":
                current = (float(tokens[i + 1]), float(tokens[i + 2]))
                points.append(current)
                i += 3
            elif t == "C":
                c = [current] + [(float(tokens[i + k]), float(tokens[i + k + 1])) for k in (1, 3, 5)]
                for u in np.linspace(0, 1, 129)[1:]:  # extremes within 0.002 mm on a 100 mm arc
                    w = [(1 - u) ** 3, 3 * u * (1 - u) ** 2, 3 * u * u * (1 - u), u**3]
                    points.append((sum(w[k] * c[k][0] for k in range(4)), sum(w[k] * c[k][1] for k in range(4))))
                current = c[3]
                i += 7
            else:  # Z
                i += 1
        if points:
            loops[kind].append(points)
        a, b, c, d, e, f = matrix
        loops[kind][start:] = [[(a * x + c * y + e, b * x + d * y + f) for x, y in p] for p in loops[kind][start:]]
    flip = lambda pts: [(x, height - y) for x, y in pts]  # noqa: E731
    return {k: [flip(p) for p in v] for k, v in loops.items()}


# --- DXF: CUT entities chained into loops by their end points.
def dxf_chains(doc):
    msp = doc.modelspace()
    cut = [e for e in msp if e.dxf.layer == "CUT"]
    for e in cut:
        if e.dxftype() not in ("LINE", "ARC", "CIRCLE"):
            fail(f"unexpected {e.dxftype()} on CUT")
    parent = list(range(len(cut)))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    ends, degree = {}, {}

    def snap(p):
        # The end point already seen within 0.002 mm, else this one: rounding to a grid would
        # split two ends that straddle a grid line.
        cell = (round(p[0] * 1000), round(p[1] * 1000))
        for dx in (-2, -1, 0, 1, 2):
            for dy in (-2, -1, 0, 1, 2):
                if (cell[0] + dx, cell[1] + dy) in degree:
                    return (cell[0] + dx, cell[1] + dy)
        return cell
    for i, e in enumerate(cut):
        if e.dxftype() == "CIRCLE":
            continue
        if e.dxftype() == "LINE":
            pts = [e.dxf.start, e.dxf.end]
        else:
            pts = [e.start_point, e.end_point]
        for p in pts:
            key = snap(p)
            degree[key] = degree.get(key, 0) + 1
            if key in ends:
                parent[find(i)] = find(ends[key])
            ends[key] = i
    open_ends = [k for k, d in degree.items() if d % 2]
    if open_ends:
        fail(f"{len(open_ends)} open end(s) on CUT, e.g. {open_ends[:3]}: something not closed is cut")
    groups = {}
    for i in range(len(cut)):
        groups.setdefault(find(i), []).append(cut[i])
    boxes = []
    for entities in groups.values():
        ext = ezdxf.bbox.extents(entities)
        boxes.append([ext.extmin.x, ext.extmin.y, ext.extmax.x, ext.extmax.y])
    return boxes


def check_dxf(path, report):
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    if auditor.has_errors:
        fail(f"{path}: ezdxf audit found errors: {[str(e.message) for e in auditor.errors][:3]}")
    if doc.header.get("$INSUNITS") != 4:
        fail(f"{path}: $INSUNITS is {doc.header.get('$INSUNITS')}, not 4 (mm)")
    if not doc.header.get("$ACADVER"):
        fail(f"{path}: no $ACADVER")
    layers = {layer.dxf.name: layer.dxf.color for layer in doc.layers}
    if layers.get("CUT") != 1 or layers.get("ENGRAVE") != 5:
        fail(f"{path}: layers {layers}: CUT must be red (1) and ENGRAVE blue (5)")
    msp = doc.modelspace()
    engrave = [e for e in msp if e.dxf.layer == "ENGRAVE"]
    arcs = sum(1 for e in msp if e.dxf.layer == "CUT" and e.dxftype() in ("ARC", "CIRCLE"))
    if not engrave:
        fail(f"{path}: nothing to engrave: the labels are missing")
    return dxf_chains(doc), arcs, engrave


def main():
    sliceform, model = sys.argv[1], sys.argv[2]
    extra = sys.argv[3:]
    with tempfile.TemporaryDirectory() as tmp:
        if model in SOLIDS:
            model = make_solid(tmp, model)
        out = os.path.join(tmp, "out")
        run = subprocess.run([sliceform, "design", model, "-o", out, *extra], capture_output=True, text=True)
        print(run.stdout)
        if run.returncode != 0:
            fail(f"design exited {run.returncode}: {run.stderr}")
        report = json.load(open(os.path.join(out, "report.json")))
        sheets = report["sheets"]
        count, (width, height) = sheets["count"], sheets["size_mm"]
        margin = sheets["margin_mm"]
        for key in ("count", "size_mm", "utilisation"):
            if key not in sheets:
                fail(f"report sheets lacks {key}")

        # Slots left without their partner's id: the total is the patches' sum.
        for key in ("partner_labels_missing", "partner_labels_on_leaders"):
            total = sum(p[key] for p in report["patches"])
            if report.get(key) != total:
                fail(f"report {key} {report.get(key)}, patches sum to {total}")
            if any(p[key] > p["partner_labels"] + p["partner_labels_missing"] for p in report["patches"]):
                fail(f"a patch has more {key} than slots")
        if any(len(p["partner_labels_missing_for"]) != p["partner_labels_missing"] for p in report["patches"]):
            fail("a patch's partner_labels_missing_for does not name each slot left without a label")

        # PDF: pages, page size, and every page renders.
        info = subprocess.run(["pdfinfo", os.path.join(out, "sheets.pdf")], capture_output=True, text=True).stdout
        pages = int(re.search(r"Pages:\s+(\d+)", info).group(1))
        size = re.search(r"Page size:\s+([0-9.]+) x ([0-9.]+) pts", info)
        if pages != count:
            fail(f"{pages} PDF pages for {count} sheets")
        if abs(float(size.group(1)) - width * 72 / 25.4) > 0.5 or abs(float(size.group(2)) - height * 72 / 25.4) > 0.5:
            fail(f"PDF page {size.group(0)} is not {width} x {height} mm")
        subprocess.run(["pdftoppm", "-r", "36", "-png", os.path.join(out, "sheets.pdf"), os.path.join(tmp, "page")], check=True)
        rendered = sorted(f for f in os.listdir(tmp) if f.startswith("page"))
        if len(rendered) != count:
            fail(f"pdftoppm rendered {len(rendered)} pages for {count} sheets")
        for f in rendered:
            image = matplotlib.image.imread(os.path.join(tmp, f))
            red = np.sum((image[:, :, 0] > 0.8) & (image[:, :, 1] < 0.6))
            if red < 100:
                fail(f"{f}: almost no red cut lines rendered ({red} pixels)")

        # Patches against the SVG and DXF of their sheet.
        svg = [svg_loops(os.path.join(out, f"sheet-{s + 1}.svg"), height) for s in range(count)]
        dxf = [check_dxf(os.path.join(out, f"sheet-{s + 1}.dxf"), report) for s in range(count)]
        placed_outers = {s: [] for s in range(count)}
        for patch in report["patches"]:
            s = patch["sheet"] - 1
            if not 0 <= s < count:
                fail(f"{patch['id']} on sheet {patch['sheet']} of {count}")
            outer = placed(patch["outline"][0], patch["placement"])
            placed_outers[s].append((patch["id"], outer))
            want = bbox(outer)
            if want[0] < margin - TOL or want[1] < margin - TOL or want[2] > width - margin + TOL or want[3] > height - margin + TOL:
                fail(f"{patch['id']} leaves the margins: {want}")
            in_svg = sum(1 for s2 in range(count) for loop in svg[s2]["cut"] if s2 == s and same_box(bbox(loop), want))
            in_dxf = sum(1 for box in dxf[s][0] if same_box(box, want))
            if in_svg != 1 or in_dxf != 1:
                fail(f"{patch['id']}: its outline ({want[2] - want[0]:.3f} x {want[3] - want[1]:.3f} mm) is found "
                     f"{in_svg} time(s) in sheet-{s + 1}.svg and {in_dxf} in sheet-{s + 1}.dxf, not once")
        if model.endswith("sphere.brep") and sum(d[1] for d in dxf) == 0:
            fail("a sphere's sheets have no ARC or CIRCLE on CUT: its circles were not kept")

        # No overlaps, and every engraved mark inside a patch of its sheet.
        for s in range(count):
            paths = [Path(outer) for _, outer in placed_outers[s]]
            xs, ys = np.meshgrid(np.arange(0, width, 0.5) + 0.25, np.arange(0, height, 0.5) + 0.25)
            grid = np.column_stack((xs.ravel(), ys.ravel()))
            cover = sum(p.contains_points(grid).astype(int) for p in paths)
            if cover.max() > 1:
                fail(f"sheet {s + 1}: patches overlap at {grid[np.argmax(cover)]}")
            for e in dxf[s][2]:
                ext = ezdxf.bbox.extents([e])
                mid = ((ext.extmin.x + ext.extmax.x) / 2, (ext.extmin.y + ext.extmax.y) / 2)
                if not any(p.contains_point(mid) for p in paths):
                    fail(f"sheet {s + 1}: an engraved mark at {mid} is on no patch")
        print(f"ok: {len(report['patches'])} patches on {count} sheet(s), each found once in SVG and DXF; "
              f"{sum(d[1] for d in dxf)} arcs/circles on CUT; no overlaps")


if __name__ == "__main__":
    main()
