# SPDX-License-Identifier: LGPL-2.1-or-later
# GUI smoke test, run by gui_smoke.sh inside FreeCAD under Xvfb: the workbench is listed
# and activates, its command slices a selected solid, and the 3D view is saved as a PNG.
# Writes "ok" or the failure to $SLICEFORM_SMOKE_RESULT, then leaves FreeCAD at once.
import os
import traceback

import FreeCAD
import FreeCADGui

result_path = os.environ["SLICEFORM_SMOKE_RESULT"]
try:
    assert "SliceformWorkbench" in FreeCADGui.listWorkbenches(), "workbench not listed"
    FreeCADGui.activateWorkbench("SliceformWorkbench")
    assert FreeCADGui.activeWorkbench().name() == "SliceformWorkbench", "workbench not active"
    assert "Sliceform_Slices" in FreeCADGui.listCommands(), "command not registered"
    doc = FreeCAD.newDocument("Smoke")
    torus = doc.addObject("Part::Torus", "Torus")
    torus.Radius1, torus.Radius2 = 20, 6
    doc.recompute()
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(torus)
    FreeCADGui.runCommand("Sliceform_Slices")
    sliced = [o for o in doc.Objects if o.Name.startswith("Slices")]
    assert len(sliced) == 1, "the command added {} slice objects".format(len(sliced))
    assert len(sliced[0].Shape.Faces) >= 32, "too few section faces"
    torus.Visibility = False
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewIsometric()
    view.fitAll()
    view.saveImage(os.environ["SLICEFORM_SMOKE_PNG"], 800, 600, "White")
    assert os.path.getsize(os.environ["SLICEFORM_SMOKE_PNG"]) > 1000, "empty screenshot"
    outcome = "ok"
except Exception:
    outcome = traceback.format_exc()
with open(result_path, "w") as f:
    f.write(outcome)
os._exit(0)
