# SPDX-License-Identifier: LGPL-2.1-or-later
# Sliceform workbench registration (GUI only). Commands are imported in Initialize(), when
# the user first activates the workbench, not at FreeCAD start-up.
import FreeCAD
import FreeCADGui


class SliceformWorkbench(FreeCADGui.Workbench):
    MenuText = FreeCAD.Qt.QT_TRANSLATE_NOOP("Workbench", "Sliceform")
    ToolTip = FreeCAD.Qt.QT_TRANSLATE_NOOP("Workbench", "Turn a solid into a paper sliceform: slotted patches that fold flat")

    def __init__(self):
        import sliceform_gui

        # Translations (Resources/translations/Sliceform_<lang>.qm) load with FreeCAD's
        # language, before any of our strings is shown.
        FreeCADGui.addLanguagePath(sliceform_gui.translations_path())
        FreeCADGui.updateLocale()
        self.__class__.Icon = sliceform_gui.icon_path("Sliceform.svg")
        self.__class__.MenuText = FreeCAD.Qt.translate("Workbench", self.MenuText)
        self.__class__.ToolTip = FreeCAD.Qt.translate("Workbench", self.ToolTip)

    def Initialize(self):
        from sliceform_gui import commands

        import sliceform_gui

        names = commands.register()
        self.appendToolbar("Sliceform", names)
        self.appendMenu("&Sliceform", names)
        # The preferences page's icon is looked up by name: preferences-sliceform.svg.
        FreeCADGui.addIconPath(sliceform_gui.icon_path(""))
        from sliceform_gui import preferences

        FreeCADGui.addPreferencePage(preferences.PreferencesPage, "Sliceform")

    def GetClassName(self):
        return "Gui::PythonWorkbench"


FreeCADGui.addWorkbench(SliceformWorkbench())
