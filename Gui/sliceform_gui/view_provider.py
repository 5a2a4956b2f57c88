# SPDX-License-Identifier: LGPL-2.1-or-later
"""View providers of the Sliceform feature and its children. The feature shows, under it in
the tree, the objects that link to it (its pages and patches; a patch shows its drawing on
the sheet), the way TechDraw shows views under their page. Deleting the feature deletes
them and shows the source again. Double-click edits in the task panel."""
import FreeCAD
import FreeCADGui

from sliceform_gui import icon_path


class _Stateless:
    # Nothing to save: 0.20 calls __getstate__, later versions dumps.
    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    def dumps(self):
        return None

    def loads(self, state):
        return None


class ViewProviderSliceform(_Stateless):
    def __init__(self, vobj):
        vobj.Proxy = self
        self.Object = vobj.Object
        # Paper: light card colour, lit from both sides (the patches are faces, not solids).
        vobj.ShapeColor = (0.93, 0.88, 0.76)
        vobj.Lighting = "Two side"
        # Paper, not a sketch: a 2D object shows as wireframe unless told otherwise.
        if "Flat Lines" in vobj.listDisplayModes():
            vobj.DisplayMode = "Flat Lines"

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        return icon_path("Sliceform_Create.svg")

    def claimChildren(self):
        from sliceform_app import lookup

        obj = self.Object
        return lookup.pages_of(obj) + lookup.patches_of(obj)

    def onDelete(self, vobj, subelements):
        """Deletes the children with the feature (in the same Delete step) and shows the
        source again."""
        from sliceform_app import making

        obj = vobj.Object
        source = obj.Source
        making.remove_children(obj)
        if source is not None and source.ViewObject is not None:
            source.ViewObject.Visibility = True
        return True

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


class ViewProviderPatch(_Stateless):
    def __init__(self, vobj):
        vobj.Proxy = self
        self.Object = vobj.Object
        vobj.ShapeColor = (0.93, 0.88, 0.76)
        vobj.Lighting = "Two side"
        # Paper, not a sketch: a 2D object shows as wireframe unless told otherwise.
        if "Flat Lines" in vobj.listDisplayModes():
            vobj.DisplayMode = "Flat Lines"

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        return icon_path("Sliceform_Slices.svg")

    def claimChildren(self):
        from sliceform_app import lookup

        drawings = [lookup.sheet_patch_of(self.Object)] + lookup.engraving_parts_of(self.Object)
        return [d for d in drawings if d is not None]


class ViewProviderSheetPatch(_Stateless):
    def __init__(self, vobj):
        vobj.Proxy = self
        self.Object = vobj.Object

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        return icon_path("Sliceform_Export.svg")
