# SPDX-License-Identifier: LGPL-2.1-or-later
"""The workbench's commands. register() adds only the commands whose dependencies load:
without the compiled core it says so in the report view and registers none. Commands that
change the document run inside a transaction, so Undo takes them back in one step."""
import FreeCAD
import FreeCADGui

from sliceform_gui import icon_path


def _selected_solid():
    for obj in FreeCADGui.Selection.getSelection():
        if obj.isDerivedFrom("Mesh::Feature") or (hasattr(obj, "Shape") and obj.Shape.Solids):
            if not _is_sliceform(obj):
                return obj
    return None


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
            "MenuText": "Slices",
            "ToolTip": "Cut the selected solid or closed mesh into 16 sections along X and 16 "
            "along Y and add them as one compound (exact curves for CAD solids)",
        }

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and _selected_solid() is not None

    def Activated(self):
        from sliceform_app import slices

        doc = FreeCAD.ActiveDocument
        obj = _selected_solid()
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
            "MenuText": "Create sliceform",
            "ToolTip": "Design a paper sliceform of the selected solid, PartDesign body or closed "
            "mesh: slotted patches, a sketch per patch and a TechDraw page per sheet. "
            "It follows the source when the source changes.",
        }

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and _selected_solid() is not None

    def Activated(self):
        from sliceform_app import feature

        doc = FreeCAD.ActiveDocument
        source = _selected_solid()
        doc.openTransaction("Create sliceform")
        obj = feature.makeSliceform(source, doc)
        # Kept even when the design fails: the feature shows the error and can be edited.
        doc.commitTransaction()
        if obj.isValid():
            source.ViewObject.Visibility = False
        else:
            _error(obj.getStatusString())
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(obj)


class EditCommand:
    """Opens the task panel of the selected sliceform."""

    def GetResources(self):
        return {
            "Pixmap": icon_path("Sliceform_Edit.svg"),
            "MenuText": "Edit sliceform",
            "ToolTip": "Change the selected sliceform's parameters in the task panel, recompute "
            "and see the results (stability, interlocks, slot distances, sheets)",
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
            "MenuText": "Export layout",
            "ToolTip": "Write the selected sliceform's sheets into a folder: DXF per sheet for "
            "laser cutters (layers CUT and ENGRAVE, mm), SVG per sheet, a PDF to print at "
            "100 %, PNG previews, STEP/glTF of the assembly and report.json",
        }

    def IsActive(self):
        return _selected_sliceform() is not None

    def Activated(self):
        from PySide import QtGui

        obj = _selected_sliceform()
        folder = QtGui.QFileDialog.getExistingDirectory(FreeCADGui.getMainWindow(), "Export the layout into")
        if not folder:
            return
        try:
            files = obj.Proxy.write_files(folder, float(obj.FoldAngle.Value))
        except Exception as e:
            _error(e)
            return
        FreeCAD.Console.PrintMessage(
            "Sliceform: wrote {} files into {}: {}\n".format(len(files["written"]), folder, ", ".join(files["written"]))
        )


class FoldCommand:
    """Sweeps FoldAngle from popped up to nearly flat and back."""

    STEPS = 24

    def GetResources(self):
        return {
            "Pixmap": icon_path("Sliceform_Fold.svg"),
            "MenuText": "Fold animation",
            "ToolTip": "Animate the selected sliceform folding flat and popping up again "
            "(FoldAngle 90 to 10 degrees and back; the angle is restored after)",
        }

    def IsActive(self):
        return _selected_sliceform() is not None

    def Activated(self):
        from PySide import QtCore

        obj = _selected_sliceform()
        start = float(obj.FoldAngle.Value)
        down = [90 - 80 * i / self.STEPS for i in range(self.STEPS + 1)]
        angles = down + down[::-1] + [start]
        self.timer = QtCore.QTimer()

        def step():
            if not angles or not obj.isValid():
                self.timer.stop()
                return
            obj.FoldAngle = angles.pop(0)
            obj.recompute()  # only re-poses the patches: the design is kept in memory
            FreeCADGui.updateGui()

        self.timer.timeout.connect(step)
        self.timer.start(40)


class ReportCommand:
    """Shows the selected sliceform's report."""

    def GetResources(self):
        return {
            "Pixmap": icon_path("Sliceform_Report.svg"),
            "MenuText": "Show report",
            "ToolTip": "Show the selected sliceform's checks: stability certificate, interlocks, "
            "split patches, slot-to-edge distance, hinge lengths, quality, sheets; save report.json",
        }

    def IsActive(self):
        return _selected_sliceform() is not None

    def Activated(self):
        from PySide import QtGui

        obj = _selected_sliceform()
        text = obj.Report if obj.isValid() else "Error: " + obj.getStatusString()
        box = QtGui.QMessageBox(FreeCADGui.getMainWindow())
        box.setWindowTitle("{} report".format(obj.Label))
        box.setText(text or "Not computed yet: recompute the sliceform.")
        save = box.addButton("Save report.json...", QtGui.QMessageBox.ActionRole)
        box.addButton(QtGui.QMessageBox.Close)
        box.exec_()
        report = obj.Proxy.report_json()
        if box.clickedButton() == save and report:
            path, _ = QtGui.QFileDialog.getSaveFileName(box, "Save report", "report.json", "JSON (*.json)")
            if path:
                with open(path, "w") as f:
                    f.write(report)


COMMANDS = {
    "Sliceform_Create": CreateCommand,
    "Sliceform_Edit": EditCommand,
    "Sliceform_Export": ExportCommand,
    "Sliceform_Fold": FoldCommand,
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
        FreeCADGui.addCommand(name, command())
    return list(COMMANDS)
