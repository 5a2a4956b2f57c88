#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Benchmark of `sliceform design` (issue 7): median wall time per stage and peak memory per
model, against two floors (our `sliceform slice`, FreeCAD's Mesh.crossSections), and how it
scales with triangles and slices. Measures only; asserts nothing about speed.

    /usr/bin/python3 bench/run.py [MODEL ...] [--repeat 3] [--out bench/out] [--stages BUILD_DIR]
    /usr/bin/python3 bench/run.py --smoke      # CI: one small run, fails if a number is missing
"""
import argparse
import json
import math
import os
import platform
import re
import shutil
import subprocess
import sys
import tempfile
import time

import meshes
import report

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SHARED = os.path.join(ROOT, "..", "shared", "models")
OCCT = "/usr/share/opencascade/data"
CAD = (".step", ".stp", ".iges", ".igs", ".brep", ".brp")
# timings.json's stages in pipeline order; whatever else it holds is appended.
STAGES = ["slice", "reeb", "gca", "frames", "certificate", "quality", "realization", "exact patches",
          "check", "certificate again", "layout"]
# What writing each file costs, as timings.json names it, then their sum.
EXPORT = ["export drawings", "export assembly picture", "export files", "export STEP, waiting for it", "export"] + [
    "export %s, in parallel" % f for f in ("report", "booklet", "sheets PDF", "sheets PNG", "SVG", "DXF", "BREP", "glTF", "STEP")]


def median(xs):
    xs = sorted(x for x in xs if x is not None)
    if not xs:
        return None
    k = len(xs) // 2
    return xs[k] if len(xs) % 2 else (xs[k - 1] + xs[k]) / 2


def timed(cmd, cwd):
    """Runs cmd: exit code, wall s, CPU s (user and system, every thread) and peak RSS MB,
    measured here (the child's rusage from wait4: no /usr/bin/time needed, which the Debian
    13 root lacks). The host's speed swings by a quarter between hours; CPU s beside wall s
    tells work saved from a core left idle."""
    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        t0 = time.time()
        p = subprocess.Popen(cmd, cwd=cwd, stdout=out, stderr=err, text=True)
        _, status, usage = os.wait4(p.pid, 0)
        wall = time.time() - t0
        p.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0), err.seek(0)
        stdout, stderr = out.read(), err.read()
    # The program's own message, else how it ended (a signal, an exit status).
    lines = [l for l in stderr.splitlines() if l.startswith("sliceform")]
    if not lines and p.returncode < 0:
        lines = ["Command terminated by signal %d" % -p.returncode]
    elif not lines and p.returncode > 0:
        lines = ["Command exited with non-zero status %d" % p.returncode]
    return {"rc": p.returncode, "t0": t0, "wall_s": wall, "cpu_s": usage.ru_utime + usage.ru_stime,
            "rss_mb": usage.ru_maxrss / 1024,
            "stdout": stdout, "error": lines[0] if lines else None}


def design_once(cli, model, n, size, tmp):
    out = os.path.join(tmp, "design")
    shutil.rmtree(out, ignore_errors=True)
    r = timed([cli, "design", model, "--size", str(size), "-n", str(n), "-o", out], tmp)
    run = {"rc": r["rc"], "wall_s": r["wall_s"], "cpu_s": r["cpu_s"], "rss_mb": r["rss_mb"], "error": r["error"]}
    tri = re.search(r"^model .*, (\d+) triangles\)", r["stdout"], re.M)
    run["triangles"] = int(tri.group(1)) if tri else None
    if r["rc"] != 0 or not os.path.exists(os.path.join(out, "timings.json")):
        return run
    stages = {k: v / 1000 for k, v in json.load(open(os.path.join(out, "timings.json"))).items() if k != "total"}
    # timings.json times reading the model, each stage and each file written, one after the
    # other; what is left of the wall time is the process starting (loading OCCT's libraries)
    # and ending. A stage "..., in parallel" ran beside the others and is not added.
    serial = {k: v for k, v in stages.items() if not k.endswith(", in parallel")}
    stages["start + exit"] = r["wall_s"] - sum(serial.values())
    stages["export"] = sum(v for k, v in serial.items() if k.startswith("export "))
    run["stages_s"] = stages
    return run


def floor_once(cli, model, n, tmp):
    """`sliceform slice -n N` with the mesh slicer (what design slices with, CAD files too):
    read the model, cut 2 x N slices, and the two small SVGs it always writes."""
    r = timed([cli, "slice", model, "-n", str(n), "--method", "mesh"], tmp)
    per = [float(x) for x in re.findall(r"mesh slicer: ([\d.]+) ms per slice", r["stdout"])]
    return {"rc": r["rc"], "wall_s": r["wall_s"], "rss_mb": r["rss_mb"], "error": r["error"],
            "slicing_s": sum(per) * n / 1000 if len(per) == 2 else None}


def summarise(runs):
    ok = [r for r in runs if r.get("rc") == 0 and "stages_s" in r]
    names = [s for s in ["start + exit", "read"] + STAGES if any(s in r["stages_s"] for r in ok)]
    names += sorted({s for r in ok for s in r["stages_s"]} - set(names) - set(EXPORT)) + EXPORT
    return {"runs": len(runs), "ok": len(ok), "wall_s": median(r["wall_s"] for r in ok),
            "cpu_s": median(r["cpu_s"] for r in ok),
            "rss_mb": max((r["rss_mb"] for r in ok if r["rss_mb"]), default=None),
            "triangles": next((r["triangles"] for r in runs if r.get("triangles")), None),
            "stages_s": {s: median(r["stages_s"].get(s) for r in ok) for s in names} if ok else {},
            "errors": sorted({r["error"] for r in runs if r.get("error")})}


def bench_model(cli, model, n, size, repeat, tmp):
    d = summarise([design_once(cli, model, n, size, tmp) for _ in range(repeat)])
    floors = [floor_once(cli, model, n, tmp) for _ in range(repeat)]
    d["floor_s"] = median(f["wall_s"] for f in floors if f["rc"] == 0)
    d["floor_slicing_s"] = median(f["slicing_s"] for f in floors if f["rc"] == 0)
    d["ratio_to_floor"] = d["wall_s"] / d["floor_s"] if d["wall_s"] and d["floor_s"] else None
    d["floor_ok"] = sum(f["rc"] == 0 for f in floors)
    d["errors"] = sorted(set(d["errors"]) | {"floor: " + f["error"] for f in floors if f["error"]})
    return d


def freecad_reference(models, n, size, repeat, tmp):
    job, out = os.path.join(tmp, "fc_job.json"), os.path.join(tmp, "fc_out.json")
    json.dump({"models": models, "slices": n, "size": size, "repeat": repeat}, open(job, "w"))
    env = dict(os.environ, HOME=os.path.join(tmp, "home"), SLICEFORM_FC_JOB=job, SLICEFORM_FC_OUT=out)
    os.makedirs(env["HOME"], exist_ok=True)
    subprocess.run(["freecadcmd", os.path.join(HERE, "fc_sections.py")], env=env, capture_output=True)
    return json.load(open(out)) if os.path.exists(out) else {m: {"error": "freecadcmd failed"} for m in models}


def freecad_edits(meshes, repeat, build, tmp):
    """bench/fc_edit.py in freecadcmd, the workbench installed from BUILD into a throwaway HOME
    (the installed package's, if BUILD was not made with CMake)."""
    job, out = os.path.join(tmp, "fc_edit_job.json"), os.path.join(tmp, "fc_edit_out.json")
    json.dump({"meshes": meshes, "repeat": repeat, "directions": ["given", "auto"]}, open(job, "w"))
    home = os.path.join(tmp, "edit-home")
    env = dict(os.environ, HOME=home, XDG_DATA_HOME=os.path.join(home, ".local", "share"),
               XDG_CONFIG_HOME=os.path.join(home, ".config"), SLICEFORM_FC_JOB=job, SLICEFORM_FC_OUT=out)
    if os.path.exists(os.path.join(build, "cmake_install.cmake")):
        subprocess.run(["cmake", "--install", build, "--prefix",
                        os.path.join(home, ".local", "share", "FreeCAD", "Mod", "Sliceform")], capture_output=True)
    p = subprocess.run(["freecadcmd", os.path.join(HERE, "fc_edit.py")], env=env, capture_output=True, text=True)
    if not os.path.exists(out):
        return {"error": "freecadcmd exited %d: %s" % (p.returncode, p.stderr.strip()[-300:])}
    return json.load(open(out))


def slope(xs, ys):
    """Least-squares slope of log y against log x."""
    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys) if x and y]
    if len(pts) < 2:
        return None
    mx, my = sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sum((x - mx) ** 2 for x, _ in pts)


def scaling(cli, model, size, repeat, tmp):
    verts, tris = meshes.read_mesh(model)
    levels, k = [], 0
    for target in (5e3, 2e4, 8e4, 3e5):  # 4^k times the original, nearest in log
        k = max(k, round(math.log(target / len(tris), 4)))
        levels.append(k)
    by_tris = []
    for k in sorted(set([0] + levels)):
        v, t = verts, tris
        for _ in range(k):
            v, t = meshes.subdivide(v, t)
        path = os.path.join(tmp, "subdivided-%d.off" % k)
        meshes.write_off(path, v, t)
        by_tris.append(dict(summarise([design_once(cli, path, 128, size, tmp) for _ in range(repeat)]),
                            subdivisions=k, triangles=len(t)))
    by_slices = [dict(summarise([design_once(cli, model, n, size, tmp) for _ in range(repeat)]), slices=n)
                 for n in (64, 128, 256, 512)]
    tx = [r["triangles"] for r in by_tris]
    sx = [r["slices"] for r in by_slices]
    stages = by_tris[0]["stages_s"].keys()
    return {"model": model, "by_triangles": by_tris, "by_slices": by_slices, "slopes": {
        "time_vs_triangles": slope(tx, [r["wall_s"] for r in by_tris]),
        "time_vs_slices": slope(sx, [r["wall_s"] for r in by_slices]),
        "memory_vs_triangles": slope(tx, [r["rss_mb"] for r in by_tris]),
        "memory_vs_slices": slope(sx, [r["rss_mb"] for r in by_slices]),
        "stage_time_vs_triangles": {s: slope(tx, [r["stages_s"].get(s) for r in by_tris]) for s in stages},
        "stage_time_vs_slices": {s: slope(sx, [r["stages_s"].get(s) for r in by_slices]) for s in stages}}}


def stages_benchmark(build, tmp):
    exe, out = os.path.join(build, "bench", "stages_benchmark"), os.path.join(tmp, "stages.json")
    p = subprocess.run([exe, "--benchmark_out=" + out, "--benchmark_out_format=json"], capture_output=True)
    if p.returncode != 0 or not os.path.exists(out):
        return {"error": "%s exited %d" % (exe, p.returncode)}
    return json.load(open(out))


def default_models():
    if os.path.isdir(SHARED):
        ok = [os.path.join(SHARED, m + ".obj") for m in ("bunny-lowres", "fandisk", "rocker-arm", "cow", "spot")]
        return ok, [os.path.join(SHARED, m + ".obj") for m in ("teapot", "stanford-bunny")]
    return [OCCT + "/stl/propeller.stl", OCCT + "/stl/sh1.stl", OCCT + "/step/screw.step"], []


def machine():
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?")
    mem = next(int(l.split()[1]) for l in open("/proc/meminfo") if l.startswith("MemTotal"))
    osname = next((l.split("=", 1)[1].strip().strip('"') for l in open("/etc/os-release")
                   if l.startswith("PRETTY_NAME")), platform.platform())
    return {"nproc": os.cpu_count(), "cpu": cpu, "ram_gb": round(mem / 2 ** 20, 1), "os": osname,
            "load_average": os.getloadavg()}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("models", nargs="*", help="default: ../shared/models, else OCCT's occt-misc parts")
    ap.add_argument("--repeat", type=int, default=3, help="runs per figure (median)")
    ap.add_argument("-n", "--slices", type=int, default=128)
    ap.add_argument("--size", type=float, default=150)
    ap.add_argument("--out", default=os.path.join(HERE, "out"))
    ap.add_argument("--cli", default=os.path.join(ROOT, "build", "App", "cli", "sliceform"))
    ap.add_argument("--stages", metavar="BUILD_DIR", help="also run BUILD_DIR/bench/stages_benchmark")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"),
                    help="the build whose workbench the FreeCAD edits use (default: build/)")
    ap.add_argument("--edit-meshes", nargs="*", help="meshes for the FreeCAD edit rows (default: fandisk.obj "
                    "from ../shared/models, else OCCT's sh1.stl), besides a box minus a cylinder")
    ap.add_argument("--scaling-model", help="default: spot.obj, else bunny-lowres.obj, else OCCT's sh1.stl")
    ap.add_argument("--no-freecad", action="store_true", help="no FreeCAD sections or edits")
    ap.add_argument("--no-scaling", action="store_true")
    ap.add_argument("--smoke", action="store_true", help="one icosphere run at 32 slices; exit 1 on a failure")
    a = ap.parse_args()
    a.models = [os.path.abspath(m) for m in a.models]  # the runs start in a temporary folder
    os.makedirs(a.out, exist_ok=True)
    tmp = tempfile.mkdtemp(prefix="sliceform-bench-")
    # Run a copy: a rebuild of build/ by someone else during the run must not break it.
    a.cli = shutil.copy2(a.cli, os.path.join(tmp, "sliceform"))
    refused = []
    if a.smoke:
        a.repeat, a.slices, a.no_freecad, a.no_scaling = 1, 32, True, True
        if not a.models:
            a.models = [os.path.join(tmp, "icosphere.off")]
            meshes.write_off(a.models[0], *meshes.icosphere(3))
    elif not a.models:
        a.models, refused = default_models()
    def git(*c):  # "" where git is not installed (the Debian 13 root the suite keeps)
        try:
            return subprocess.run(["git", "-C", ROOT] + list(c), capture_output=True, text=True).stdout.strip()
        except FileNotFoundError:
            return ""

    result = {"machine": machine(), "command": " ".join([sys.executable] + sys.argv),
              "commit": git("rev-parse", "--short", "HEAD"), "tree_dirty": bool(git("status", "--porcelain", "App")),
              "cli_built": time.strftime("%Y-%m-%d %H:%M:%S", time.localtime(os.stat(a.cli).st_mtime)),
              "slices": a.slices, "size_mm": a.size, "repeat": a.repeat, "models": {}, "refused": {}}
    for m in refused:  # open meshes: refused with a message, or (small holes filled) benchmarked
        r = timed([a.cli, "design", m, "--size", str(a.size), "-o", os.path.join(tmp, "refused")], tmp)
        if r["rc"] == 0:
            a.models.append(m)
            result["holes_filled"] = result.get("holes_filled", []) + [m]
        else:
            result["refused"][m] = {"rc": r["rc"], "error": r["error"]}
    for m in a.models:
        print("benchmarking", m, file=sys.stderr)
        result["models"][m] = bench_model(a.cli, m, a.slices, a.size, a.repeat, tmp)
    if not a.no_freecad:
        for m, fc in freecad_reference(a.models, a.slices, a.size, a.repeat, tmp).items():
            result["models"][m]["freecad"] = fc
    if not a.no_freecad:
        edit_meshes = a.edit_meshes if a.edit_meshes is not None else [
            next(p for p in (os.path.join(SHARED, "fandisk.obj"), OCCT + "/stl/sh1.stl") if os.path.exists(p))]
        print("FreeCAD edits", file=sys.stderr)
        result["freecad_edits"] = freecad_edits([os.path.abspath(m) for m in edit_meshes], a.repeat, a.build, tmp)
    if not a.no_scaling:
        model = a.scaling_model or next((p for p in (os.path.join(SHARED, "spot.obj"),
                                                       os.path.join(SHARED, "bunny-lowres.obj"))
                                         if os.path.exists(p)), OCCT + "/stl/sh1.stl")
        print("scaling", model, file=sys.stderr)
        result["scaling"] = scaling(a.cli, model, a.size, a.repeat, tmp)
    if a.stages:
        result["stages_benchmark"] = stages_benchmark(a.stages, tmp)
    result["machine"]["load_average_end"] = os.getloadavg()
    json.dump(result, open(os.path.join(a.out, "bench.json"), "w"), indent=1)
    md = report.markdown(result)
    open(os.path.join(a.out, "bench.md"), "w").write(md)
    print(md)
    if "scaling" in result:
        report.plot(result["scaling"], os.path.join(a.out, "scaling.png"))
    shutil.rmtree(tmp, ignore_errors=True)
    missing = report.missing(result)
    if missing:
        print("missing or failed: " + "; ".join(missing), file=sys.stderr)
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
