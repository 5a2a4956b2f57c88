# SPDX-License-Identifier: LGPL-2.1-or-later
"""Run by scripts/test-package in `freecadcmd`, in a clean Debian root where only the
freecad-sliceform package (and what it depends on) is installed: the workbench is found in
FreeCAD's system Mod folder, the compiled core on the system Python path, and a sliceform
of a torus is designed and its files written. Prints one line starting with
SLICEFORM-PACKAGE-OK when all of that holds (freecadcmd exits 0 even when a script fails)."""
import json
import os
import sys
import tempfile
import traceback

import FreeCAD


def check(condition, what):
    if not condition:
        raise AssertionError(what)


def main():
    import sliceform_app
    from sliceform_app import feature, native

    check(sliceform_app.ADDON_DIR == "/usr/share/freecad/Mod/Sliceform", "addon at " + sliceform_app.ADDON_DIR)
    core = native()
    check(core.__file__.startswith("/usr/lib/python3/dist-packages/sliceform_native."), "core at " + core.__file__)
    user_mod = os.path.join(os.path.expanduser("~"), ".local", "share", "FreeCAD", "Mod")
    check(not os.path.exists(os.path.join(user_mod, "Sliceform")), "a user Mod folder copy")
    metadata = FreeCAD.Metadata("/usr/share/freecad/Mod/Sliceform/package.xml")
    check(metadata.Name == "Sliceform", "package.xml name " + metadata.Name)
    check(metadata.Version == core.__version__, "package.xml {} vs core {}".format(metadata.Version, core.__version__))

    doc = FreeCAD.newDocument("Package")
    torus = doc.addObject("Part::Torus", "Torus")
    torus.Radius1, torus.Radius2 = 40, 15
    doc.recompute()
    sliceform = feature.makeSliceform(torus, Slices=24)
    check(sliceform.isValid(), sliceform.getStatusString())
    check(sliceform.Stable, "not stable: " + str(sliceform.Report))
    check(sliceform.Interlocks == 0, "interlocks")
    check(sliceform.PatchCount >= 4, "patches: {}".format(sliceform.PatchCount))
    check(len(sliceform.Shape.Faces) == sliceform.PatchCount, "faces")
    folder = tempfile.mkdtemp()
    written = sliceform.Proxy.write_files(sliceform, folder)["written"]
    for name in ("report.json", "sheets.pdf", "sheet-1.dxf", "sheet-1.svg", "assembly.step", "instructions.pdf"):
        check(name in written and os.path.getsize(os.path.join(folder, name)) > 0, name)
    with open(os.path.join(folder, "report.json")) as f:
        report = json.load(f)
    check(len(report["patches"]) == sliceform.PatchCount, "report patches")
    print(
        "SLICEFORM-PACKAGE-OK FreeCAD {} Python {}.{} core {}: {} patches, {} sheets".format(
            ".".join(FreeCAD.Version()[:3]),
            sys.version_info.major,
            sys.version_info.minor,
            core.__file__,
            sliceform.PatchCount,
            sliceform.SheetCount,
        )
    )


try:
    main()
except Exception:
    traceback.print_exc()
    print("SLICEFORM-PACKAGE-FAILED")
