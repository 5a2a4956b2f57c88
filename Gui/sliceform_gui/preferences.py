# SPDX-License-Identifier: LGPL-2.1-or-later
"""Edit > Preferences > Sliceform: the defaults new sliceforms take, made from the core's
parameter schema like the task panel (label, range, step, unit, default and help of each
field). Stored under BaseApp/Preferences/Mod/Sliceform as FreeCAD's preference widgets
store them (numbers as floats, Slices as an integer, the sheet as its index) and read by
sliceform_app.feature.preferred_properties."""
import FreeCAD
from PySide import QtGui

from sliceform_gui import fields

translate = FreeCAD.Qt.translate


def _rows():
    """(property, schema row) for each preference, in feature.PREFERRED's order."""
    from sliceform_app import feature, parameters

    by_property = {s["property"]: s for s in parameters.schema() if s["property"]}
    return [(name, by_property[name]) for name in feature.PREFERRED]


class PreferencesPage:
    """The page FreeCAD shows (addPreferencePage with a class: it makes one per dialog and
    calls loadSettings, then saveSettings on OK or Apply)."""

    def __init__(self):
        self.form = QtGui.QWidget()
        self.form.setWindowTitle(translate("Sliceform", "Sliceform"))
        outer = QtGui.QVBoxLayout(self.form)
        group = QtGui.QGroupBox(translate("Sliceform", "Defaults for new sliceforms (material, sheets, slicing)"))
        layout = QtGui.QFormLayout(group)
        outer.addWidget(group)
        outer.addStretch()
        self.fields = {}
        for name, spec in _rows():
            if spec["kind"] == "choice":
                box = QtGui.QComboBox()
                box.addItems(spec["choices"])
            else:
                box = fields.field(group, spec, spec["default"])
            box.setToolTip(translate("App::Property", spec["help"]))
            # Schema labels are in the translation template (scripts/update-translations).
            layout.addRow(translate("Sliceform", spec["label"]), box)
            self.fields[name] = box

    def loadSettings(self):
        from sliceform_app import feature

        chosen = feature.preferred_properties()
        for name, spec in _rows():
            value = chosen.get(name, spec["default"])
            box = self.fields[name]
            if spec["kind"] == "choice":
                box.setCurrentIndex(max(0, box.findText(value)))
            else:
                fields.set_value(box, value)

    def saveSettings(self):
        from sliceform_app import feature

        group = FreeCAD.ParamGet(feature.PREFERENCES)
        for name, spec in _rows():
            box = self.fields[name]
            if spec["kind"] == "choice":
                group.SetInt(name, box.currentIndex())
            elif spec["kind"] == "integer":
                group.SetInt(name, int(fields.value(box)))
            else:
                group.SetFloat(name, float(fields.value(box)))
