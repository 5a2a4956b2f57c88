#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Buildability sweep (issue 14): `sliceform design` on every model at hand, each design
checked on its own by ../shared/tools/check_report.py, and every face of its assembly
through OCCT's BRepCheck (bench/faces_valid.py). A model passes when it builds (exit 0),
the checker accepts it and every face is valid, or when it is refused (exit 1, 3 or 4) with one
clear line that is not an internal error. Anything else fails the sweep: a design we call
buildable that the checker rejects, a crash, a run that does not end.

    /usr/bin/python3 bench/sweep.py                      # OCCT's samples and ../shared/models
    /usr/bin/python3 bench/sweep.py --occt               # only /usr/share/opencascade/data
    /usr/bin/python3 bench/sweep.py MODEL ... -- --thickness 3 --clearance 0.1 --sheet 600x400
    /usr/bin/python3 bench/sweep.py --jobs 2             # two models at once (scripts/test)

Writes a Markdown table to stdout (and --out DIR/sweep.md, sweep.json); exit 1 when a model
fails.
"""
import argparse
import concurrent.futures
import glob
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SHARED = os.path.join(ROOT, "..", "shared")
OCCT = "/usr/share/opencascade/data"
KINDS = (".brep", ".step", ".stp", ".iges", ".igs", ".stl", ".obj", ".off")
REFUSED = (1, 3, 4)  # cannot be built / unusable model / parameter out of range


def occt_models():
    found = []
    for sub in ("occ", "step", "iges", "stl"):
        found += [p for p in glob.glob(os.path.join(OCCT, sub, "*")) if p.lower().endswith(KINDS)]
    return sorted(found)


def shared_models():
    return sorted(glob.glob(os.path.join(SHARED, "models", "*.obj")) +
                  glob.glob(os.path.join(SHARED, "models", "cgal", "*.off")))


def run_one(cli, checker, model, args, out, timeout):
    name = os.path.basename(model)
    folder = os.path.join(out, name)
    row = {"model": name, "path": model}
    t0 = time.time()
    try:
        p = subprocess.run([cli, "design", model, "-o", folder] + args, capture_output=True, text=True,
                           timeout=timeout)
    except subprocess.TimeoutExpired:
        row.update(rc=None, time_s=timeout, verdict="FAIL", reason="did not end in %d s" % timeout)
        return row
    row["time_s"] = round(time.time() - t0, 2)
    row["rc"] = p.returncode
    message = [l for l in p.stderr.splitlines() if l.startswith("sliceform:")]
    row["message"] = message[-1] if message else ""
    report_path = os.path.join(folder, "report.json")
    if os.path.exists(report_path):
        with open(report_path) as f:
            rep = json.load(f)
        row.update(patches=len(rep["patches"]), sheets=rep["sheets"]["count"],
                   min_spacing=rep.get("min_patch_spacing_mm"), min_finger=rep.get("min_finger_mm"),
                   split=rep["split_patches"], interlocks=rep["interlocks"]["remaining"],
                   labels_missing=rep.get("partner_labels_missing"),
                   labels_on_leaders=rep.get("partner_labels_on_leaders"),
                   iou=(rep["quality"]["silhouette_iou_u"], rep["quality"]["silhouette_iou_v"],
                        rep["quality"]["volume_iou"]))
        c = subprocess.run([sys.executable, checker, report_path], capture_output=True, text=True)
        row["checker"] = json.loads(c.stdout) if c.stdout.strip() else {"ok": False, "problems": [c.stderr]}
    if p.returncode == 0:
        # The assembly a CAD program reads: every face must pass OCCT's BRepCheck.
        f = subprocess.run([sys.executable, os.path.join(HERE, "faces_valid.py"),
                            os.path.join(folder, "assembly.brep")], capture_output=True, text=True)
        faces = json.loads(f.stdout) if f.returncode == 0 else {"faces": 0, "invalid": [[-1, f.stderr.strip()]]}
        row["faces"], row["invalid_faces"] = faces["faces"], faces["invalid"]
        ok = row.get("checker", {}).get("ok", False)
        row["verdict"] = "builds" if ok and not faces["invalid"] else "FAIL"
        reasons = [] if ok else ["exit 0 but the checker rejects it: %s" % row.get("checker", {}).get("problems")]
        if faces["invalid"]:
            reasons.append("assembly faces failing BRepCheck: %s" % faces["invalid"][:3])
        row["reason"] = "; ".join(reasons)
    elif p.returncode in REFUSED and row["message"] and "internal error" not in row["message"]:
        row["verdict"] = "refused"
        row["reason"] = row["message"][len("sliceform: "):]
    else:
        row["verdict"] = "FAIL"
        row["reason"] = row["message"] or "exit %s without a message" % p.returncode
    return row


def fmt(v, digits=2):
    if v is None:
        return "-"
    if isinstance(v, float):
        return "%.*f" % (digits, v)
    return str(v)


def table(rows):
    lines = ["| model | exit | verdict | patches | sheets | min spacing mm | min finger mm | split | interlocks "
             "| labels missing | faces (invalid) | IoU U / V / vol | s | reason |",
             "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---|"]
    for r in rows:
        iou = "/".join(fmt(x, 3) for x in r["iou"]) if r.get("iou") else "-"
        faces = "%d (%d)" % (r["faces"], len(r["invalid_faces"])) if "faces" in r else "-"
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["model"], fmt(r.get("rc")), r["verdict"], fmt(r.get("patches")), fmt(r.get("sheets")),
            fmt(r.get("min_spacing")), fmt(r.get("min_finger")), fmt(r.get("split")), fmt(r.get("interlocks")),
            fmt(r.get("labels_missing")), faces, iou, fmt(r.get("time_s"), 1), r.get("reason", "").replace("|", "/")[:160]))
    return "\n".join(lines)


def main():
    argv = sys.argv[1:]
    design_args = []
    if "--" in argv:
        k = argv.index("--")
        argv, design_args = argv[:k], argv[k + 1:]
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("models", nargs="*", help="model files (default: OCCT's samples and ../shared/models)")
    ap.add_argument("--occt", action="store_true", help="only the OCCT samples under " + OCCT)
    ap.add_argument("--cli", default=os.path.join(ROOT, "build", "App", "cli", "sliceform"))
    ap.add_argument("--checker", default=os.path.join(SHARED, "tools", "check_report.py"))
    ap.add_argument("--timeout", type=int, default=300, help="seconds a model may take (default 300)")
    ap.add_argument("--out", help="keep the designs and write sweep.md and sweep.json here")
    ap.add_argument("--jobs", type=int, default=1,
                    help="models designed at once (default 1; more makes each model's seconds a shared "
                         "machine's, and a time limit reached sooner)")
    a = ap.parse_args(argv)
    models = a.models or (occt_models() if a.occt else occt_models() + shared_models())
    if not models:
        sys.exit("sweep: no models (install occt-misc, or give model files)")
    if not os.path.exists(a.checker):
        sys.exit("sweep: no checker at " + a.checker)
    out = a.out or tempfile.mkdtemp(prefix="sliceform-sweep-")
    os.makedirs(out, exist_ok=True)
    # A design uses both cores only in parts (the slot search's patch states, the exact
    # patches); a second model designed beside it takes the rest.
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
        futures = [pool.submit(run_one, a.cli, a.checker, m, design_args, out, a.timeout) for m in models]
        for f in concurrent.futures.as_completed(futures):
            r = f.result()
            print("sweep: %-28s %-8s %5.1f s  %s" % (r["model"], r["verdict"], r["time_s"], r.get("reason", "")[:100]),
                  file=sys.stderr, flush=True)
        rows = [f.result() for f in futures]
    text = table(rows)
    print(text)
    if a.out:
        with open(os.path.join(out, "sweep.md"), "w") as f:
            f.write(text + "\n")
        with open(os.path.join(out, "sweep.json"), "w") as f:
            json.dump(rows, f, indent=1)
    failed = [r["model"] for r in rows if r["verdict"] == "FAIL"]
    print("\n%d models: %d build, %d refused, %d FAIL%s" % (
        len(rows), sum(r["verdict"] == "builds" for r in rows), sum(r["verdict"] == "refused" for r in rows),
        len(failed), (": " + ", ".join(failed)) if failed else ""))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
