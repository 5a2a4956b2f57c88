# SPDX-License-Identifier: LGPL-2.1-or-later
"""instructions.pdf, the assembly booklet: one step per patch, in report.json's assembly
order, every patch exactly once; each step page shows the highlight colour (the patch the
step adds); the page count stays near one page per six steps.

Usage: instructions_check.py SLICEFORM MODEL
"""
import json
import os
import re
import subprocess
import sys
import tempfile

import matplotlib.image
import numpy as np



def fail(message):
    print("FAIL", message)
    sys.exit(1)


def main():
    sliceform, model = sys.argv[1:3]
    with tempfile.TemporaryDirectory() as out:
        run = subprocess.run([sliceform, "design", model, "-n", "48", "-o", out], capture_output=True, text=True)
        if run.returncode != 0:
            fail(f"design exit {run.returncode}: {run.stderr}")
        report = json.load(open(os.path.join(out, "report.json")))
        pdf = os.path.join(out, "instructions.pdf")
        text = subprocess.run(["pdftotext", "-layout", pdf, "-"], capture_output=True, text=True, check=True).stdout
        steps = [(int(n), i) for n, i in re.findall(r"Step (\d+): ([UV]\d+)", text)]
        steps.sort()
        ids = [i for _, i in steps]
        order = report["assembly_order"]
        patches = [p["id"] for p in report["patches"]]
        if [n for n, _ in steps] != list(range(1, len(steps) + 1)):
            fail(f"steps are not numbered 1..{len(steps)}")
        if len(ids) != len(patches) or sorted(ids) != sorted(patches):
            fail(f"{len(ids)} steps for {len(patches)} patches, or a patch twice or missing")
        if ids != order:
            fail("the steps are not in the report's assembly order")
        # Each step marks the slots it names on the patch's own outline, with the partner's id:
        # beyond the step headings, as many bare ids on the step pages as the steps name.
        step_pages = "\f".join(text.split("\f")[1:])
        named = sum(len(re.findall(r"[UV]\d+", ids_)) for ids_ in re.findall(r"onto ([UV0-9, ]+)\.", step_pages))
        bare = len([w for w in step_pages.split() if re.fullmatch(r"[UV]\d+", w)])
        if named == 0 or bare - len(ids) < named:
            fail(f"{bare - len(ids)} slot marks on the patches' outlines for {named} slots named in the steps")
        pages = int(re.search(r"^Pages:\s+(\d+)$", subprocess.run(["pdfinfo", pdf], capture_output=True,
                                                                   text=True).stdout, re.M).group(1))
        if pages != 1 + (len(ids) + 5) // 6:
            fail(f"{pages} pages for {len(ids)} steps")
        subprocess.run(["pdftoppm", "-r", "30", "-png", pdf, os.path.join(out, "page")], check=True)
        images = sorted(f for f in os.listdir(out) if f.startswith("page"))
        for f in images[1:]:
            image = matplotlib.image.imread(os.path.join(out, f))[:, :, :3]
            # The highlight (#E8603C) or its x-ray blend over paper: red well above green;
            # neither paper colour (cream 0.98/0.89/0.72, blue) nor the grey edges come near.
            near = ((image[:, :, 0] - image[:, :, 1]) > 0.25).sum()
            if near < 20:
                fail(f"{f}: no highlighted patch in its step pictures ({near} pixels)")
    print(f"ok: {len(ids)} steps on {pages} pages, every patch once, in assembly order")


main()
