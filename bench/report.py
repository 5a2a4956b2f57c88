# SPDX-License-Identifier: LGPL-2.1-or-later
"""bench/run.py's output: Markdown tables, the scaling plot, and the list of missing numbers."""
import math
import os

SCALING_STAGES = ["slice", "reeb", "gca", "quality", "realization", "exact patches", "layout", "export"]


def f(x, scale=1.0, digits=2):
    return "—" if x is None else "%.*f" % (digits, x * scale)


def name(path):
    return os.path.basename(path)


def markdown(r):
    m = r["machine"]
    out = ["# Sliceform benchmark", "",
           "Machine: %d cores, %s, %.1f GB RAM, %s; load average %.2f at the start, %.2f at the end."
           % (m["nproc"], m["cpu"], m["ram_gb"], m["os"], m["load_average"][0], m["load_average_end"][0]),
           "", "Command: `%s`; commit %s%s, `sliceform` built %s." % (
               r["command"], r.get("commit"), " with uncommitted changes in App/" if r.get("tree_dirty") else "",
               r.get("cli_built")), "",
           "`sliceform design MODEL --size %g -n %d -o TMP`, median of %d runs (peak memory: the largest). "
           "Floor: `sliceform slice MODEL -n %d --method mesh` (read and 2 x %d mesh slices). FreeCAD: "
           "Mesh.crossSections (Part.Shape.slices for CAD files) through the same 2 x %d planes, at the "
           "centres of %d equal cells of the bounding box along X and Y, model scaled to %g mm."
           % (r["size_mm"], r["slices"], r["repeat"], r["slices"], r["slices"], r["slices"], r["slices"],
              r["size_mm"]), "",
           "| model | triangles | end-to-end s | CPU s | floor s | × floor | FreeCAD sections s | peak MB | runs ok |",
           "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for path, d in r["models"].items():
        fc = d.get("freecad", {})
        fcs = f(fc.get("median_s"), 1, 3) + (" (Part)" if fc.get("method") == "Part.Shape.slices" else "")
        out.append("| %s | %s | %s | %s | %s | %s | %s | %s | %d/%d |" % (
            name(path), d["triangles"] or "—", f(d["wall_s"]), f(d.get("cpu_s")), f(d["floor_s"], 1, 3),
            f(d["ratio_to_floor"], 1, 1), fcs, f(d["rss_mb"], 1, 0), d["ok"], d["runs"]))
        for e in d["errors"]:
            out.append("| | %s | | | | | | | |" % e.replace("|", "/"))
    out.append("")
    for path, e in r.get("refused", {}).items():
        out.append("Refused (exit %d): %s  " % (e["rc"], e["error"]))
    for path in r.get("holes_filled", []):
        out.append("%s is open, but its holes are small: `design` fills them, so it is benchmarked.  " % name(path))
    models = [p for p in r["models"] if r["models"][p]["stages_s"]]
    if models:
        out += ["", "Median time per stage, ms, as timings.json gives it (read: reading and scaling the "
                "model; export X: writing file X; start + exit: the rest of the wall time):", "",
                "| stage | " + " | ".join(name(p) for p in models) + " |",
                "|---|" + "---:|" * len(models)]
        stages = list(r["models"][models[0]]["stages_s"])
        for s in stages:
            out.append("| %s | %s |" % (s, " | ".join(f(r["models"][p]["stages_s"].get(s), 1000, 0) for p in models)))
    if "freecad_edits" in r:
        out += edits_md(r["freecad_edits"], r["repeat"])
    if "scaling" in r:
        out += scaling_md(r["scaling"])
    if "stages_benchmark" in r:
        out += stages_md(r["stages_benchmark"])
    return "\n".join(out) + "\n"


EDIT_PARTS = ["sliceform", "patches", "sheet drawings", "TechDraw views", "other"]


def edits_md(e, repeat):
    if "error" in e:
        return ["", "FreeCAD edits: " + e["error"]]
    out = ["", "## FreeCAD edit", "",
           "FreeCAD %s, `freecadcmd` (bench/fc_edit.py): a property set in a transaction, the document "
           "recomputed and the transaction closed (the children synced), as the property editor does; median "
           "of %d edits, each to a value not used before. s: all of that, what the user waits for (FreeCAD "
           "0.20's TechDraw draws the sheets inside it); drawn s: until every sheet view is drawn; then the "
           "recomputes' seconds by kind of object. Radius: the source's cylinder." % (e.get("freecad", "?"), repeat), "",
           "| model, directions | patches | edit | s | drawn s | " + " | ".join(EDIT_PARTS) + " |",
           "|---|---:|---|---:|---:|" + "---:|" * len(EDIT_PARTS)]
    for row, d in e.items():
        if row == "freecad":
            continue
        if "error" in d:
            out.append("| %s | | %s | | | %s|" % (name(row), d["error"].replace("|", "/"), "| " * len(EDIT_PARTS)))
            continue
        out.append("| %s | %d | create | %s | | %s|" % (name(row), d["patches"], f(d["create_s"]), "| " * len(EDIT_PARTS)))
        for prop, x in d["edits"].items():
            out.append("| | | %s%s | %s | %s | %s |" % (
                prop, "" if x["valid"] else " (invalid)", f(x["recompute_s"]), f(x["drawn_s"]),
                " | ".join(f(x["parts_s"].get(k)) for k in EDIT_PARTS)))
    return out


def scaling_md(s):
    head = "| %s | end-to-end s | peak MB | " + " | ".join(x + " ms" for x in SCALING_STAGES) + " |"
    rule = "|---:|---:|---:|" + "---:|" * len(SCALING_STAGES)
    out = ["", "## Scaling: %s" % name(s["model"]), "",
           "Triangles by midpoint subdivision (each triangle into 4; the shape is unchanged), 128 slices:", "",
           head % "triangles", rule]
    row = lambda key, d: "| %s | %s | %s | %s |" % (d[key], f(d["wall_s"]), f(d["rss_mb"], 1, 0), " | ".join(
        f(d["stages_s"].get(x), 1000, 0) for x in SCALING_STAGES))
    out += [row("triangles", d) for d in s["by_triangles"]]
    out += ["", "Slices per direction, original mesh:", "", head % "slices", rule]
    out += [row("slices", d) for d in s["by_slices"]]
    sl = s["slopes"]
    out += ["", "Log-log least-squares slopes (1 = linear):", "", "| | vs triangles | vs slices |", "|---|---:|---:|",
            "| end-to-end time | %s | %s |" % (f(sl["time_vs_triangles"]), f(sl["time_vs_slices"])),
            "| peak memory | %s | %s |" % (f(sl["memory_vs_triangles"]), f(sl["memory_vs_slices"]))]
    for st, v in sl["stage_time_vs_triangles"].items():
        out.append("| %s time | %s | %s |" % (st, f(v), f(sl["stage_time_vs_slices"].get(st))))
    return out


def stages_md(b):
    if "error" in b:
        return ["", "Stage benchmark: " + b["error"]]
    out = ["", "## Google Benchmark of the core stages (bench/stages_benchmark)", "",
           "| benchmark | wall ms | CPU ms | ms per slice |", "|---|---:|---:|---:|"]
    for x in b["benchmarks"]:
        if x.get("run_type") == "aggregate" and x.get("aggregate_name") != "median":
            continue
        unit = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[x.get("time_unit", "ns")]
        out.append("| %s | %s | %s | %s |" % (x["name"].replace("/iterations:1/repeats:3", ""),
                                             f(x["real_time"] * unit, 1, 1), f(x["cpu_time"] * unit, 1, 1),
                                             f(x.get("ms_per_slice"), 1, 2)))
    return out


def plot(s, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import NullFormatter, ScalarFormatter
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, key, rows, label in ((axes[0], "triangles", s["by_triangles"], "triangles (128 slices)"),
                                 (axes[1], "slices", s["by_slices"], "slices per direction")):
        x = [d[key] for d in rows]
        ax.loglog(x, [d["wall_s"] for d in rows], "o-k", lw=2, label="end-to-end")
        for st in ("layout", "realization", "gca", "slice", "export"):
            ax.loglog(x, [d["stages_s"].get(st) for d in rows], ".-", lw=1, label=st)
        ax.loglog(x, [rows[0]["wall_s"] * xi / x[0] for xi in x], ":", color="grey", label="linear")
        # Memory on its own axis spanning as many decades as the time axis: equal slopes look equal.
        mb = [d["rss_mb"] for d in rows]
        lo, hi = ax.get_ylim()
        mid = math.sqrt(min(mb) * max(mb))
        mem = ax.twinx()
        mem.loglog(x, mb, "s--", color="tab:purple", label="peak MB")
        mem.set_ylim(mid / math.sqrt(hi / lo), mid * math.sqrt(hi / lo))
        mem.yaxis.set_major_formatter(ScalarFormatter())
        mem.set_ylabel("peak memory, MB (dashed)", color="tab:purple")
        ax.set_xticks(x)
        ax.xaxis.set_major_formatter(ScalarFormatter())
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.set_xlabel(label)
        ax.set_ylabel("median time, s")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7, loc="upper left")
    fig.suptitle("sliceform design, %s: time and memory" % name(s["model"]))
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def missing(r):
    """Every run must succeed and every number be there (the smoke test's only check)."""
    bad = []
    for path, d in r["models"].items():
        if d["ok"] != d["runs"] or d["floor_ok"] != d["runs"]:
            bad.append("%s: %d/%d design runs, %d floor runs ok %s" % (name(path), d["ok"], d["runs"],
                                                                    d["floor_ok"], d["errors"]))
        for k in ("wall_s", "cpu_s", "rss_mb", "floor_s", "floor_slicing_s", "ratio_to_floor", "triangles"):
            if d.get(k) is None:
                bad.append("%s: no %s" % (name(path), k))
        bad += ["%s: no %s time" % (name(path), s) for s, v in d["stages_s"].items() if v is None]
        if "freecad" in d and d["freecad"].get("median_s") is None:
            bad.append("%s: FreeCAD reference %s" % (name(path), d["freecad"].get("error")))
    for d in r.get("scaling", {}).get("by_triangles", []) + r.get("scaling", {}).get("by_slices", []):
        if d["ok"] != d["runs"] or d["wall_s"] is None:
            bad.append("scaling run failed: %s" % d["errors"])
    edits = r.get("freecad_edits", {})
    if "error" in edits:
        bad.append("FreeCAD edits: " + edits["error"])
    bad += ["FreeCAD edits, %s: %s" % (row, d["error"]) for row, d in edits.items() if row != "freecad" and "error" in d]
    if "error" in r.get("stages_benchmark", {}):
        bad.append(r["stages_benchmark"]["error"])
    return bad
