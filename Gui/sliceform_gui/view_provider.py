# SPDX-License-Identifier: LGPL-2.1-or-later
"""View provider of the Sliceform feature: its icon, its children in the tree (patch
sketches, sheet geometry, TechDraw pages; not the source, which stays beside it), and
double-click to edit in the task panel."""
import FreeCADGui

from sliceform_gui import icon_path


class ViewProviderSliceform:
    def __init__(self, vobj):
        vobj.Proxy = self
        self.Object = vobj.Object
        # Paper: light card colour, lit from both sides (the patches are faces, not solids).
        vobj.ShapeColor = (0.93, 0.88, 0.76)
        vobj.Lighting = "Two side"

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        return icon_path("Sliceform_Create.svg")

    def claimChildren(self):
        obj = self.Object
        children = [getattr(obj, "PatchGroup", None), getattr(obj, "SheetGroup", None)]
        children += list(getattr(obj, "Pages", []) or [])
        return [c for c in children if c is not None]

    def setEdit(self, vobj, mode=0):
        if mode != 0:
            return None
        from sliceform_gui import task_panel

        FreeCADGui.Control.showDialog(task_panel.SliceformTaskPanel(vobj.Object))
        return True

    def unsetEdit(self, vobj, mode=0):
        FreeCADGui.Control.closeDialog()
        return True

    def doubleClicked(self, vobj):
        FreeCADGui.ActiveDocument.setEdit(vobj.Object.Name)
        return True

    # Nothing to save: 0.20 calls __getstate__, later versions dumps.
    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    def dumps(self):
        return None

    def loads(self, state):
        return None
