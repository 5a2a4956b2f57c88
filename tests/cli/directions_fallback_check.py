# SPDX-License-Identifier: LGPL-2.1-or-later
"""`sliceform design MODEL` with no slicing directions given, on a model whose file axes give
no buildable design (OCCT's TR12J_OCC.stl: a patch in pieces): the run says so, designs in
the best other frame (--directions auto), exits 0 with a design the independent checker
passes and report.json naming the frame; with `--directions given` asked for, the same
model is refused (exit 1) and no other frame is tried. The time limit covers the whole run:
when the file's axes used it up, no other frame is tried either, and the run says why.

Usage: directions_fallback_check.py SLICEFORM MODEL CHECK_REPORT
"""
import json
import subprocess
import sys
import tempfile


def design(sliceform, model, out, *extra):
    run = subprocess.run([sliceform, "design", model, "-o", out, *extra], capture_output=True, text=True)
    print(run.stdout[-2500:], run.stderr[-1500:])
    return run


def main():
    sliceform, model, checker = sys.argv[1:4]
    with tempfile.TemporaryDirectory() as out:
        run = design(sliceform, model, out, "--directions", "given")
        assert run.returncode == 1, "exit %d: the file's axes were expected not to build" % run.returncode
        assert "trying others" not in run.stdout, "--directions given was asked for: no other frame"
        assert "cannot be built" in run.stderr
    with tempfile.TemporaryDirectory() as out:
        run = design(sliceform, model, out, "--time-limit", "0.05")
        assert run.returncode == 1, "exit %d: the time limit ran out" % run.returncode
        assert "trying others" not in run.stdout, "other frames tried after the time limit ran out"
        assert "the time limit (0.05 s) left no time to try others" in run.stdout
        assert "the time limit (0.05 s) ran out" in run.stderr
    with tempfile.TemporaryDirectory() as out:
        run = design(sliceform, model, out)
        assert run.returncode == 0, "exit %d" % run.returncode
        assert "the file's axes give no buildable design" in run.stdout
        assert "trying others (--directions auto)" in run.stdout
        assert "directions auto: the file's axes gave no buildable design" in run.stdout
        subprocess.run(["/usr/bin/python3", checker, out + "/report.json"], check=True)
        report = json.load(open(out + "/report.json"))
        timings = json.load(open(out + "/timings.json"))
    d = report["directions"]
    assert d["mode"] == "auto" and d["frames"][d["chosen"]]["design"]["buildable"], d
    assert d["why"].startswith("the file's axes gave no buildable design; "), d["why"]
    assert report["verdict"]["buildable"], report["verdict"]
    chosen = d["frames"][d["chosen"]]
    p = report["parameters"]
    assert all(abs(a - b) < 1e-3 for a, b in zip(p["u"] + p["v"], chosen["u"] + chosen["v"]))
    assert (p["u"], p["v"]) != ([1, 0, 0], [0, 1, 0]), "the file's axes are in parameters"
    assert timings.get("directions (the file's axes, not buildable)", 0) > 0, sorted(timings)
    print("ok:", chosen["name"], d["why"])


main()
