#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""What `--directions auto` costs (issue 18): per model, the median wall time of
`sliceform design M` in the file's frame (--directions given), with --directions auto, and in
the frame auto chose given as --u/--v (the one design auto cannot do without), every file
written each time. Measures only; asserts nothing about speed.

    /usr/bin/python3 bench/directions.py MODEL ... [--repeat 3] [--out FILE.json] [-- DESIGN OPTIONS]

Options after `--` go to every design (e.g. `-- --fill-holes` for an open mesh).
"""
import argparse
import json
import os
import shutil
import sys
import tempfile

import run

ROOT = run.ROOT


def one(cli, model, extra, tmp):
    """One design; `extra` holds the options after `--` and the frame's."""
    out = os.path.join(tmp, "design")
    shutil.rmtree(out, ignore_errors=True)
    r = run.timed([cli, "design", model, "--size", "150", "-o", out] + extra, tmp)
    report = os.path.join(out, "report.json")
    if r["rc"] not in (0, 1) or not os.path.exists(report):
        return {"wall_s": None, "error": r["error"] or "exit %d" % r["rc"]}
    rep = json.load(open(report))
    sheets = rep.get("sheets", {}).get("count")
    q = rep.get("quality", {})
    silhouette = [q.get("silhouette_iou_" + a) for a in "uvw"]
    return {"wall_s": r["wall_s"], "buildable": rep.get("verdict", {}).get("buildable", False),
            "u": rep["parameters"]["u"], "v": rep["parameters"]["v"], "patches": len(rep.get("patches", [])),
            "sheets": sheets, "volume_iou": q.get("volume_iou"),
            "silhouette_iou": sum(silhouette) / 3 if None not in silhouette else None}


def bench(cli, model, repeat, options, tmp):
    row = {}
    for name, extra in (("given", ["--directions", "given"]), ("auto", ["--directions", "auto"])):
        runs = [one(cli, model, options + extra, tmp) for _ in range(repeat)]
        row[name] = dict(runs[0], wall_s=run.median(r["wall_s"] for r in runs))
    a = row["auto"]
    if a.get("u"):
        frame = ["--u", ",".join(repr(x) for x in a["u"]), "--v", ",".join(repr(x) for x in a["v"])]
        runs = [one(cli, model, options + frame, tmp) for _ in range(repeat)]
        row["chosen"] = dict(runs[0], wall_s=run.median(r["wall_s"] for r in runs))
    return row


def design_cell(x):
    """buildable, volume IoU, mean silhouette IoU, patches, sheets"""
    if not x.get("wall_s"):
        return "-"
    iou = lambda v: "%.2f" % v if v is not None else "-"
    return "%s, %s, %s, %s, %s" % ("yes" if x["buildable"] else "no", iou(x.get("volume_iou")),
                                   iou(x.get("silhouette_iou")), x.get("patches"), x.get("sheets"))


def table(rows):
    lines = ["| model | given s | auto s | chosen frame alone s | auto / given | auto / chosen alone "
             "| given: buildable, volume IoU, silhouette IoU, patches, sheets | auto: the same |",
             "|---|" + "---:|" * 5 + "---|---|"]
    for model, r in rows.items():
        g, a, c = r["given"], r["auto"], r.get("chosen", {})
        ratio = lambda x, y: "%.1f" % (x / y) if x and y else "-"
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %s |" % (
            os.path.basename(model), *("%.2f" % x["wall_s"] if x.get("wall_s") else "-" for x in (g, a, c)),
            ratio(a.get("wall_s"), g.get("wall_s")), ratio(a.get("wall_s"), c.get("wall_s")),
            design_cell(g), design_cell(a)))
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("models", nargs="+")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--cli", default=os.path.join(ROOT, "build", "App", "cli", "sliceform"))
    ap.add_argument("--out", help="also write the rows as JSON here")
    argv = sys.argv[1:]
    options = argv[argv.index("--") + 1:] if "--" in argv else []  # for every design
    args = ap.parse_args(argv[:argv.index("--")] if "--" in argv else argv)
    rows = {}
    with tempfile.TemporaryDirectory() as tmp:
        for m in args.models:
            rows[m] = bench(args.cli, os.path.abspath(m), args.repeat, options, tmp)
            print(os.path.basename(m), json.dumps({k: v.get("wall_s") for k, v in rows[m].items()}), file=sys.stderr)
    print(table(rows))
    if args.out:
        json.dump(rows, open(args.out, "w"), indent=1)


if __name__ == "__main__":
    main()
