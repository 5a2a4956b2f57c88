# SPDX-License-Identifier: LGPL-2.1-or-later
"""The workbench's commands. register() adds only the commands whose dependencies load:
without the compiled core it says so in the report view and registers none. Commands that
change the document run inside a transaction, so Undo takes them back in one step."""
import FreeCAD
import FreeCADGui

from PySide.QtCore import QT_TRANSLATE_NOOP

translate = FreeCAD.Qt.translate
# pylupdate5 (scripts/update-translations) finds a marked string only when its context is on
# the call's own line and no comma trails the text: keep calls so, the schema test checks.

from sliceform_gui import icon_path


def _selected_solid():
    for obj in FreeCADGui.Selection.getSelection():
        if obj.isDerivedFrom("Mesh::Feature") or (hasattr(obj, "Shape") and obj.Shape.Solids):
            if not _is_sliceform(obj):
                return obj
    return None


def _may_hold_a_solid(obj):
    """What IsActive asks, every time the GUI polls the commands: the object's type only.
    Whether it really holds a solid (its shape's solids, a mesh's closedness) is asked when
    the command runs, which says so if not."""
    return (obj.isDerivedFrom("Part::Feature") or obj.isDerivedFrom("Mesh::Feature")) and not _is_sliceform(obj)


def _solid_for_command():
    """The selected solid or mesh; None, with a message, when the selection holds none."""
    obj = _selected_solid()
    if obj is None:
        _error(FreeCAD.Qt.translate("Sliceform", "select a solid, a PartDesign body or a closed mesh first"))
    return obj


def _is_sliceform(obj):
    from sliceform_app import feature

    return isinstance(getattr(obj, "Proxy", None), feature.Sliceform)


def _selected_sliceform():
    for obj in FreeCADGui.Selection.getSelection():
        if _is_sliceform(obj):
            return obj
    return None


def _error(message):
    FreeCAD.Console.PrintError("Sliceform: {}\n".format(message))


class SlicesCommand:
    """Cuts the selected solid or mesh along X and Y and adds the sections."""

    def GetResources(self):
        return {
            "Pixmap": icon_path("Sliceform_Slices.svg"),
            "MenuText": QT_TRANSLATE_NOOP("Sliceform_Slices", "Slices"),
            "ToolTip": QT_TRANSLATE_NOOP("Sliceform_Slices", "Cut the selected solid or closed mesh into 16 sections along X and 16 "
                "along Y and add them as one compound (exact curves for CAD solids)"),
        }

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and any(
            _may_hold_a_solid(o) for o in FreeCADGui.Selection.getSelection())

    def Activated(self):
        from sliceform_app import slices

        doc = FreeCAD.ActiveDocument
        obj = _solid_for_command()
        if obj is None:
            return
        doc.openTransaction("Sliceform slices")
        try:
            slices.make_slices(doc, obj)
        except Exception as e:  # the core's message is for the user
            doc.abortTransaction()
            _error(e)
            return
        doc.commitTransaction()
        doc.recompute()


class CreateCommand:
    """Adds a parametric sliceform of the selected solid, body or mesh."""

    def GetResources(self):
        return {
            "Pixmap": icon_path("Sliceform_Create.svg"),
            "MenuText": QT_TRANSLATE_NOOP("Sliceform_Create", "Create sliceform"),
            "Accel": "S, C",
            "ToolTip": QT_TRANSLATE_NOOP("Sliceform_Create",
                "Design a paper sliceform of the selected solid, PartDesign body or closed mesh: "
                "slotted patches, each on its plane and on its sheet, and a TechDraw page per "
                "sheet. It follows the source when the source changes."),
        }

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and any(
            _may_hold_a_solid(o) for o in FreeCADGui.Selection.getSelection())

    def Activated(self):
        from sliceform_app import feature

        doc = FreeCAD.ActiveDocument
        source = _solid_for_command()
        if source is None:
            return
        doc.openTransaction("Create sliceform")
        # A feature made here chooses its slicing directions for the model (unless the
        # preference Directions says "given"); made from Python (makeSliceform) it keeps the
        # property's default, the directions given, as documents from before the property do.
        directions = FreeCAD.ParamGet(feature.PREFERENCES).GetString("Directions", "auto")
        directions = "given" if directions == "given" else "auto"
        # Through the console, so the Python console and a recorded macro show the call.
        before = {o.Name for o in doc.Objects}
        FreeCADGui.addModule("sliceform_app.feature")
        FreeCADGui.doCommand(
            "sliceform_app.feature.makeSliceform(FreeCAD.ActiveDocument.getObject({!r}), Directions={!r})".format(
                source.Name, directions
            )
        )
        made = [o for o in doc.Objects if o.Name not in before and _is_sliceform(o)]
        if not made:
            doc.abortTransaction()
            return
        obj = made[0]
        # Kept even when the design fails: the feature shows the error (FreeCAD reports it
        # once) and can be edited; the source is hidden either way, Delete shows it again.
        source.ViewObject.Visibility = False
        doc.commitTransaction()
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(obj)


class EditCommand:
    """Opens the task panel of the selected sliceform."""

    def GetResources(self):
        return {
            "Pixmap": icon_path("Sliceform_Edit.svg"),
            "MenuText": QT_TRANSLATE_NOOP("Sliceform_Edit", "Edit sliceform"),
            "ToolTip": QT_TRANSLATE_NOOP("Sliceform_Edit", "Change the selected sliceform's parameters in the task panel, recompute "
                "and see the results (stability, interlocks, slot distances, sheets)"),
        }

    def IsActive(self):
        return _selected_sliceform() is not None and not FreeCADGui.Control.activeDialog()

    def Activated(self):
        FreeCADGui.ActiveDocument.setEdit(_selected_sliceform().Name)


class ExportCommand:
    """Writes the layout and the assembly for printers and laser cutters."""

    def GetResources(self):
        return {
            "Pixmap": icon_path("Sliceform_Export.svg"),
            "MenuText": QT_TRANSLATE_NOOP("Sliceform_Export", "Export layout"),
            "Accel": "S, E",
            "ToolTip": QT_TRANSLATE_NOOP("Sliceform_Export", "Write the selected sliceform's sheets into a folder: DXF per sheet for "
                "laser cutters (layers CUT and ENGRAVE, mm), SVG per sheet, a PDF to print at "
                "100 %, PNG previews, STEP/glTF of the assembly and report.json"),
        }

    def IsActive(self):
        return _selected_sliceform() is not None

    def Activated(self):
        from PySide import QtGui

        obj = _selected_sliceform()
        folder = QtGui.QFileDialog.getExistingDirectory(
            FreeCADGui.getMainWindow(), translate("Sliceform", "Export the layout into")
        )
        if not folder:
            return
        try:
            files = obj.Proxy.write_files(obj, folder)
        except Exception as e:
            _error(e)
            return
        FreeCAD.Console.PrintMessage(
            translate("Sliceform", "Sliceform: wrote {} files into {}: {}").format(
                len(files["written"]), folder, ", ".join(files["written"])
            )
            + "\n"
        )


class FoldCommand:
    """Sweeps FoldAngle from popped up to nearly flat and back in SECONDS, however long a
    frame takes (a slow frame makes fewer frames, not a longer animation); the command again
    stops it, and the angle is put back either way."""

    SECONDS = 2.0
    FLAT = 10.0  # degrees at the middle of the sweep

    def __init__(self):
        self.timer = None

    def GetResources(self):
        return {
            "Pixmap": icon_path("Sliceform_Fold.svg"),
            "MenuText": QT_TRANSLATE_NOOP("Sliceform_Fold", "Fold animation"),
            "ToolTip": QT_TRANSLATE_NOOP("Sliceform_Fold", "Animate the selected sliceform folding flat and popping up again "
                "(FoldAngle 90 to 10 degrees and back in 2 s; the angle is restored after). "
                "Run it again to stop."),
        }

    def IsActive(self):
        return self.running() or _selected_sliceform() is not None

    def running(self):
        return self.timer is not None and self.timer.isActive()

    def Activated(self):
        import time

        from PySide import QtCore

        if self.running():
            self.stop()
            return
        obj = _selected_sliceform()
        self.obj, self.start = obj, float(obj.FoldAngle.Value)
        began = time.monotonic()
        self.shown = []  # the angles of the frames drawn, in order

        def step():
            if not obj.isValid():
                self.stop()
                return
            t = (time.monotonic() - began) / self.SECONDS
            # A slow frame must not skip the point of the animation: the first frame past
            # the middle shows the sliceform flat (on a loaded machine frames came 0.5 s
            # apart and the sweep turned back at 60 degrees).
            if t >= 0.5 and self.FLAT not in self.shown:
                t = 0.5
            elif t >= 1:
                self.stop()
                return
            # Down and up again: 90 at t = 0 and 1, FLAT at t = 0.5.
            angle = 90 - (90 - self.FLAT) * (1 - abs(2 * t - 1))
            self.shown.append(angle)
            obj.FoldAngle = angle  # re-poses the patches at once: the design is in memory
            if "Touched" in obj.State:
                obj.recompute()  # after a reopen: designed again, once
            FreeCADGui.updateGui()

        self.timer = QtCore.QTimer()
        self.timer.timeout.connect(step)
        self.timer.start(0)

    def stop(self):
        """Stops the animation and puts the angle back."""
        if self.timer is not None:
            self.timer.stop()
        obj, self.timer = getattr(self, "obj", None), None
        if obj is not None and obj.isValid():
            obj.FoldAngle = self.start
            if "Touched" in obj.State:
                obj.recompute()
            FreeCADGui.updateGui()


class ReportCommand:
    """Shows the selected sliceform's report."""

    def GetResources(self):
        return {
            "Pixmap": icon_path("Sliceform_Report.svg"),
            "MenuText": QT_TRANSLATE_NOOP("Sliceform_Report", "Show report"),
            "ToolTip": QT_TRANSLATE_NOOP("Sliceform_Report", "Show the selected sliceform's checks: stability certificate, interlocks, "
                "split patches, slot-to-edge distance, hinge lengths, quality, sheets; save report.json"),
        }

    def IsActive(self):
        return _selected_sliceform() is not None

    def Activated(self):
        from PySide import QtGui

        obj = _selected_sliceform()
        text = obj.Report if obj.isValid() else translate("Sliceform", "Error: ") + obj.getStatusString()
        box = QtGui.QMessageBox(FreeCADGui.getMainWindow())
        box.setWindowTitle(translate("Sliceform", "{} report").format(obj.Label))
        box.setText(text or translate("Sliceform", "Not computed yet: recompute the sliceform."))
        save = box.addButton(translate("Sliceform", "Save report.json..."), QtGui.QMessageBox.ActionRole)
        box.addButton(QtGui.QMessageBox.Close)
        box.exec_()
        if box.clickedButton() != save:
            return
        try:
            report = obj.Proxy.report_json(obj)  # designed now if not in memory (after a reopen)
        except Exception as e:
            _error(e)
            return
        if report:
            name = "report.json"  # the CLI's file name, not a text to translate
            path, _ = QtGui.QFileDialog.getSaveFileName(
                box, translate("Sliceform", "Save report"), name, translate("Sliceform", "JSON (*.json)")
            )
            if path:
                with open(path, "w") as f:
                    f.write(report)


class AssemblyStepsCommand:
    """Steps through the selected sliceform's assembly order in the 3D view."""

    def GetResources(self):
        from PySide.QtCore import QT_TRANSLATE_NOOP

        return {
            "Pixmap": icon_path("Sliceform_Steps.svg"),
            "MenuText": QT_TRANSLATE_NOOP("Sliceform_AssemblySteps", "Assembly steps"),
            "ToolTip": QT_TRANSLATE_NOOP("Sliceform_AssemblySteps",
                "Step through the selected sliceform's assembly order: the patches placed so far, the "
                "new one in orange, and the partners its slots go onto (a display mode: the document "
                "is not changed)"),
        }

    def IsActive(self):
        return _selected_sliceform() is not None and not FreeCADGui.Control.activeDialog()

    def Activated(self):
        from sliceform_gui import assembly_steps

        obj = _selected_sliceform()
        try:
            panel = assembly_steps.AssemblyStepsPanel(obj)
        except Exception as e:
            _error(e)
            return
        FreeCADGui.Control.showDialog(panel)


COMMANDS = {
    "Sliceform_Create": CreateCommand,
    "Sliceform_Edit": EditCommand,
    "Sliceform_Export": ExportCommand,
    "Sliceform_Fold": FoldCommand,
    "Sliceform_AssemblySteps": AssemblyStepsCommand,
    "Sliceform_Report": ReportCommand,
    "Sliceform_Slices": SlicesCommand,
}


def register():
    """Registers the commands; returns their names (empty if the core does not load)."""
    from sliceform_app import NativeModuleMissing, native

    try:
        native()
    except NativeModuleMissing as e:
        _error(e)
        return []
    for name, command in COMMANDS.items():
        made = command()
        COMMANDS_MADE.append(made)
        FreeCADGui.addCommand(name, made)
    return list(COMMANDS)


COMMANDS_MADE = []  # the command objects registered, for the GUI tests
