# SPDX-License-Identifier: LGPL-2.1-or-later
# GUI smoke test, run by gui_smoke.sh inside FreeCAD under Xvfb: the workbench is listed
# and activates with its commands and preferences page; Create makes a sliceform of a
# selected solid (stable, with sketches and a TechDraw page), Edit opens the task panel,
# Undo takes the sliceform back; the 3D view and the whole window are saved as PNGs.
# Writes "ok" or the failure to $SLICEFORM_SMOKE_RESULT, then leaves FreeCAD at once.
import os
import traceback

import FreeCAD
import FreeCADGui

result_path = os.environ["SLICEFORM_SMOKE_RESULT"]
png = os.environ["SLICEFORM_SMOKE_PNG"]
try:
    from PySide import QtGui

    assert "SliceformWorkbench" in FreeCADGui.listWorkbenches(), "workbench not listed"
    FreeCADGui.activateWorkbench("SliceformWorkbench")
    assert FreeCADGui.activeWorkbench().name() == "SliceformWorkbench", "workbench not active"
    for name in ("Sliceform_Create", "Sliceform_Edit", "Sliceform_Export", "Sliceform_Fold", "Sliceform_Report"):
        assert name in FreeCADGui.listCommands(), name + " not registered"
    # Small designs keep the test quick: the preferences page's default for new sliceforms.
    FreeCAD.ParamGet("User parameter:BaseApp/Preferences/Mod/Sliceform").SetInt("Slices", 32)

    doc = FreeCAD.newDocument("Smoke")
    torus = doc.addObject("Part::Torus", "Torus")
    torus.Radius1, torus.Radius2 = 40, 15
    beside = doc.addObject("Part::Torus", "Beside")  # the source as it looks, next to the sliceform
    beside.Radius1, beside.Radius2 = 40, 15
    beside.Placement.Base = FreeCAD.Vector(0, 130, 0)
    doc.recompute()
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(torus)
    FreeCADGui.runCommand("Sliceform_Create")
    made = [o for o in doc.Objects if o.Name.startswith("Sliceform") and o.TypeId == "Part::FeaturePython"]
    assert len(made) == 1, "Create added {} sliceforms".format(len(made))
    sliceform = made[0]
    assert sliceform.isValid(), sliceform.getStatusString()
    assert sliceform.Stable and sliceform.Interlocks == 0, sliceform.Report
    assert sliceform.Slices == 32, "the preference was not used"
    assert len(sliceform.PatchSketches) == sliceform.PatchCount and sliceform.Pages, "children missing"
    assert not torus.ViewObject.Visibility, "the source was not hidden"

    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(sliceform)
    FreeCADGui.runCommand("Sliceform_Edit")
    dialog = FreeCADGui.Control.activeDialog()
    assert dialog, "the task panel did not open"
    FreeCADGui.Control.closeDialog()
    FreeCADGui.ActiveDocument.resetEdit()

    # The 3D view: the sliceform beside its source.
    FreeCADGui.Selection.clearSelection()
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewIsometric()
    view.fitAll()
    view.saveImage(png, 1000, 700, "White")
    assert os.path.getsize(png) > 1000, "empty screenshot"
    # The whole window with the first sheet's TechDraw page beside the 3D view. Under Xvfb
    # a widget grab leaves OpenGL views blank, so the 3D view's own rendering is painted
    # into its place.
    page = sliceform.Pages[0]
    page.ViewObject.show()
    FreeCADGui.updateGui()
    main = FreeCADGui.getMainWindow()
    mdi = main.findChild(QtGui.QMdiArea)
    for window in mdi.subWindowList():
        if window.windowTitle().startswith("Start page"):
            window.close()
    FreeCADGui.updateGui()
    mdi.tileSubWindows()
    FreeCADGui.updateGui()
    gl = [w for w in main.findChildren(QtGui.QWidget) if w.metaObject().className() == "QtGLWidget" or
          "GL" in w.metaObject().className()]
    window_png = png.replace(".png", "_window.png")
    shot = main.grab()
    if gl:
        area = max(gl, key=lambda w: w.width() * w.height())
        rendered = png.replace(".png", "_gl.png")
        view.fitAll()
        view.saveImage(rendered, area.width(), area.height(), "Current")
        painter = QtGui.QPainter(shot)
        painter.drawImage(area.mapTo(main, area.rect().topLeft()), QtGui.QImage(rendered))
        painter.end()
    shot.save(window_png)
    assert os.path.getsize(window_png) > 1000, "empty window screenshot"

    # One undo takes the whole creation back.
    doc.undo()
    doc.recompute()
    left = [o for o in doc.Objects if o.TypeId == "Part::FeaturePython"]
    assert not left, "undo left {}".format([o.Name for o in left])
    outcome = "ok"
except Exception:
    outcome = traceback.format_exc()
with open(result_path, "w") as f:
    f.write(outcome)
os._exit(0)
