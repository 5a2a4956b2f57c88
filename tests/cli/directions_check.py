# SPDX-License-Identifier: LGPL-2.1-or-later
"""`sliceform design MODEL --directions auto` on a Y-up mesh: the design passes the
independent checker, report.json lists every frame tried with its score, the chosen frame
is the one in `parameters`, it was designed in full and is buildable, and the model stands
with Y up (a Y-up file read Z-up lies on its side).

Usage: directions_check.py SLICEFORM MODEL CHECK_REPORT
"""
import json
import subprocess
import sys
import tempfile


def main():
    sliceform, model, checker = sys.argv[1:4]
    with tempfile.TemporaryDirectory() as out:
        run = subprocess.run([sliceform, "design", model, "--directions", "auto", "-o", out],
                             capture_output=True, text=True)
        print(run.stdout[-2000:], run.stderr[-2000:])
        assert run.returncode == 0, "exit %d" % run.returncode
        assert "directions auto:" in run.stdout, "the summary does not say which frame won"
        subprocess.run(["/usr/bin/python3", checker, out + "/report.json"], check=True)
        report = json.load(open(out + "/report.json"))
    d = report["directions"]
    assert d["mode"] == "auto"
    frames, chosen = d["frames"], d["frames"][d["chosen"]]
    assert len(frames) >= 8, "%d frames tried" % len(frames)
    for f in frames:
        assert f["score"] > 0 or "failure" in f, f["name"]
    assert chosen["designed"] and chosen["design"]["buildable"], chosen
    best = max(f["score"] for f in frames)
    designed = [f for f in frames if f["designed"]]
    assert any(f["score"] == best for f in designed), "the best estimate was not designed"
    # Laid out are the designs that could still win: the chosen one always; one left
    # without a layout lost on buildability.
    assert chosen["design"]["sheets"] == report["sheets"]["count"], (chosen, report["sheets"]["count"])
    for f in designed:
        assert "sheets" in f["design"] or not f["design"]["buildable"], f
    p = report["parameters"]
    assert all(abs(a - b) < 1e-3 for a, b in zip(p["u"] + p["v"], chosen["u"] + chosen["v"]))
    u, v = chosen["u"], chosen["v"]
    w = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    assert chosen["stands"] and w[1] > 0.9, "not standing Y up: W = %s (%s)" % (w, chosen["name"])
    print("ok: %s, %d frames, %s" % (chosen["name"], len(frames), d["why"]))


main()
