# SPDX-License-Identifier: LGPL-2.1-or-later
"""The workbench's commands. register() adds only the commands whose dependencies load:
without the compiled core it says so in the report view and registers none."""
import FreeCAD
import FreeCADGui

from sliceform_gui import icon_path


def _selected_solid():
    for obj in FreeCADGui.Selection.getSelection():
        if obj.isDerivedFrom("Mesh::Feature") or (hasattr(obj, "Shape") and obj.Shape.Solids):
            return obj
    return None


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
            FreeCAD.Console.PrintError("Sliceform: {}\n".format(e))
            return
        doc.commitTransaction()
        doc.recompute()


COMMANDS = {"Sliceform_Slices": SlicesCommand}


def register():
    """Registers the commands; returns their names (empty if the core does not load)."""
    from sliceform_app import NativeModuleMissing, native

    try:
        native()
    except NativeModuleMissing as e:
        FreeCAD.Console.PrintError("Sliceform: {}\n".format(e))
        return []
    for name, command in COMMANDS.items():
        FreeCADGui.addCommand(name, command())
    return list(COMMANDS)
