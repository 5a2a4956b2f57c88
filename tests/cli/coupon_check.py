# SPDX-License-Identifier: LGPL-2.1-or-later
"""`sliceform coupon`: the slot widths cut in coupon.svg and coupon.dxf are what each strip's
engraved mark says (a clearance: width = thickness + clearance; E: paper from the slot to the
strip's end; F: paper between two slots), with the kerf compensated; every strip carries its
mark; the PDF has one page. The mark's text and the strip's place come from coupon.json.

Usage: coupon_check.py SLICEFORM
"""
import json
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import ezdxf

THICKNESS, CLEARANCE, KERF = 0.3, 0.2, 0.1


def fail(message):
    print("FAIL", message)
    sys.exit(1)


def svg_segments(path, height):
    """(kind, (x0, y0), (x1, y1)) of every straight piece, y up, mm."""
    out = []
    for element in ET.parse(path).getroot().iter("{http://www.w3.org/2000/svg}path"):
        colour = element.get("style", "") + " " + (element.get("stroke") or "")
        # cairo 1.16 writes style="...stroke:rgb(100%,0%,0%)", 1.18 stroke="rgb(100%, 0%, 0%)".
        kind = "cut" if re.search(r"100%,\s*0%,\s*0%|#ff0000|rgb\(255,\s*0,\s*0\)", colour) else "engrave"
        a, b, c, d, e, f = 1, 0, 0, 1, 0, 0
        if element.get("transform"):
            a, b, c, d, e, f = [float(v) for v in re.findall(r"-?[0-9.]+", element.get("transform"))]
        tokens = re.findall(r"[MLZ]|-?[0-9.]+(?:e-?[0-9]+)?", element.get("d"))
        start = current = None
        i = 0
        while i < len(tokens):
            if tokens[i] in "ML":
                x, y = float(tokens[i + 1]), float(tokens[i + 2])
                p = (a * x + c * y + e, height - (b * x + d * y + f))  # the viewBox's y runs down
                if tokens[i] == "L":
                    out.append((kind, current, p))
                else:
                    start = p
                current, i = p, i + 3
            else:
                out.append((kind, current, start))
                i += 1
    return out


def dxf_segments(path):
    doc = ezdxf.readfile(path)
    if doc.header.get("$INSUNITS") != 4:
        fail(f"{path}: not in mm")
    out = []
    for e in doc.modelspace():
        kind = "cut" if e.dxf.layer == "CUT" else "engrave"
        if e.dxftype() == "LINE":
            out.append((kind, tuple(e.dxf.start)[:2], tuple(e.dxf.end)[:2]))
        elif e.dxftype() == "LWPOLYLINE":
            pts = [tuple(p[:2]) for p in e.get_points()]
            out += [(kind, a, b) for a, b in zip(pts, pts[1:] + ([pts[0]] if e.closed else []))]
        else:
            fail(f"{path}: unexpected {e.dxftype()}")
    return out


# cairo writes SVG coordinates in 1/256 mm (24.8 fixed point): 4 µm; DXF keeps doubles.
PRECISION = {"coupon.svg": 1 / 256, "coupon.dxf": 1e-6}


def wall(segments, x, y0, y1):
    """The vertical cut at x (within 5 µm) running from y0 to y1."""
    for kind, a, b in segments:
        if kind == "cut" and abs(a[0] - b[0]) < 1e-6 and abs(a[0] - x) < 0.005:
            lo, hi = sorted((a[1], b[1]))
            if abs(lo - y0) < 0.005 and abs(hi - y1) < 0.005:
                return a[0]
    return None


def check(name, segments, coupon):
    h = KERF / 2
    for s in coupon["strips"]:
        (x0, y0), (x1, y1) = s["box"]
        top, bottom = y1 + h, s["slot_bottom_mm"] + h
        walls = []
        for lo, hi in s["slots"]:
            left, right = wall(segments, lo + h, bottom, top), wall(segments, hi - h, bottom, top)
            if left is None or right is None:
                fail(f"{name}: strip {s['text']}: no slot cut at {lo:.3f}..{hi:.3f}")
            walls.append((left - h, right + h))  # the paper's opening once the kerf is gone
        text = s["text"]
        if text.startswith("E"):
            measured, said = x1 - walls[0][1], float(text[1:])
            tolerance = 0.05  # marked to 0.1 mm
        elif text.startswith("F"):
            measured, said = walls[1][0] - walls[0][1], float(text[1:])
            tolerance = 0.05
        else:
            measured, said = walls[0][1] - walls[0][0], THICKNESS + float(text)
            tolerance = 2 * PRECISION[name] + 1e-6
            if len(walls) != 1:
                fail(f"{name}: strip {text}: {len(walls)} slots")
        if abs(measured - said) > tolerance:
            fail(f"{name}: strip {text}: cut {measured:.4f} mm where its mark says {said:.4f}")
        marks = [1 for kind, a, b in segments
                 if kind == "engrave" and x0 <= a[0] <= x0 + (x1 - x0) / 2 and y0 <= a[1] <= (y0 + y1) / 2]
        if not marks:
            fail(f"{name}: strip {text} carries no engraved mark")
    print(f"ok   {name}: {len(coupon['strips'])} strips, every slot as its mark says")


def main():
    sliceform = sys.argv[1]
    with tempfile.TemporaryDirectory() as out:
        run = subprocess.run([sliceform, "coupon", "-o", out, "--thickness", str(THICKNESS), "--clearance",
                              str(CLEARANCE), "--kerf", str(KERF)], capture_output=True, text=True)
        print(run.stdout, run.stderr)
        if run.returncode != 0:
            fail(f"exit {run.returncode}")
        coupon = json.load(open(os.path.join(out, "coupon.json")))
        width, height = coupon["sheet_mm"]
        clearances = sorted({float(s["text"]) for s in coupon["strips"] if s["text"][0].isdigit()})
        if len(clearances) != 10 or abs(clearances[3] - CLEARANCE) > 1e-9:
            fail(f"clearances {clearances}: want 10, the chosen {CLEARANCE} among them")
        if sum(1 for s in coupon["strips"] if s["text"][0].isdigit()) != 20:
            fail("not two strips per clearance")
        check("coupon.svg", svg_segments(os.path.join(out, "coupon.svg"), height), coupon)
        check("coupon.dxf", dxf_segments(os.path.join(out, "coupon.dxf")), coupon)
        pages = subprocess.run(["pdfinfo", os.path.join(out, "coupon.pdf")], capture_output=True, text=True).stdout
        if not re.search(r"^Pages:\s+1$", pages, re.M):
            fail("coupon.pdf is not one page")
        size = re.search(r"Page size:\s+([0-9.]+) x ([0-9.]+) pts", pages)
        if not size or abs(float(size.group(1)) * 25.4 / 72 - width) > 0.1 or abs(float(size.group(2)) * 25.4 / 72 - height) > 0.1:
            fail(f"coupon.pdf is not {width} x {height} mm: {size and size.group(0)}")
        for f in ("coupon.png",):
            if os.path.getsize(os.path.join(out, f)) < 1000:
                fail(f"{f} is empty")
    print("ok: coupon")


main()
