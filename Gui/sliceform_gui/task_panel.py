# SPDX-License-Identifier: LGPL-2.1-or-later
"""Task panel to edit a sliceform: the parameters a maker changes most, a Recompute button
and the results. The panel is one transaction: OK commits it as one Undo step, Cancel
aborts it, which gives back exactly the document from before the panel opened (the
children a trial Recompute added or removed included)."""
import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

from sliceform_gui import fields


QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP
translate = FreeCAD.Qt.translate


# The numbers the panel shows, by property, in this order: label, range, step and unit come
# from the core's parameter schema (the custom sheet's size is FreeCAD's own).
NUMBERS = ("Slices", "Size", "Thickness", "Clearance", "Kerf", "MinHingeLength", "MinSlotEdgeDistance", "TauA",
           "Margin", "Spacing", "SheetWidth", "SheetHeight", "FoldAngle")
_SHEET_ROW = {"min": 10.0, "max": 10000.0, "step": 10.0, "unit": "mm", "kind": "real"}
_SHEET_LABELS = {"SheetWidth": QT_TRANSLATE_NOOP("Sliceform", "Custom sheet width"),
                 "SheetHeight": QT_TRANSLATE_NOOP("Sliceform", "Custom sheet height")}


def number_rows():
    """(property, schema row) per number the panel shows."""
    from sliceform_app import parameters

    by_property = {s["property"]: s for s in parameters.schema() if s["property"]}
    return [(name, by_property.get(name) or dict(_SHEET_ROW, label=_SHEET_LABELS[name])) for name in NUMBERS]


CHOICES = (
    ("Scheme", QT_TRANSLATE_NOOP("Sliceform", "Scheme")),
    ("SheetSize", QT_TRANSLATE_NOOP("Sliceform", "Sheet")),
    ("SlotEnd", QT_TRANSLATE_NOOP("Sliceform", "Slot ends")),
)


def _value(obj, name):
    value = getattr(obj, name)
    return float(value.Value) if hasattr(value, "Value") else float(value)


class SliceformTaskPanel:
    def __init__(self, obj):
        self.obj = obj
        self.doc = obj.Document
        self.doc.openTransaction("Edit sliceform")
        self.form = QtGui.QWidget()
        self.form.setWindowTitle(translate("Sliceform", "Sliceform"))
        layout = QtGui.QFormLayout(self.form)
        # In FreeCAD's narrow Combo View a row whose label and field do not fit side by side
        # gets its field under the label, rather than the field clipped at the edge.
        layout.setRowWrapPolicy(QtGui.QFormLayout.WrapLongRows)
        layout.setFieldGrowthPolicy(QtGui.QFormLayout.AllNonFixedFieldsGrow)
        self.numbers = {}
        for name, spec in number_rows():
            box = fields.field(self.form, spec, _value(obj, name))
            box.setToolTip(translate("App::Property", obj.getDocumentationOfProperty(name)))
            # Schema labels are in the translation template too (scripts/update-translations).
            layout.addRow(translate("Sliceform", spec["label"]), box)
            self.numbers[name] = box
        self.choices = {}
        for name, label in CHOICES:
            combo = QtGui.QComboBox()
            combo.addItems(obj.getEnumerationsOfProperty(name))
            combo.setCurrentIndex(combo.findText(getattr(obj, name)))
            combo.setToolTip(translate("App::Property", obj.getDocumentationOfProperty(name)))
            layout.addRow(translate("Sliceform", label), combo)
            self.choices[name] = combo
        self.button = QtGui.QPushButton(translate("Sliceform", "Recompute"))
        self.button.clicked.connect(self.recompute)
        layout.addRow(self.button)
        self.results = QtGui.QPlainTextEdit()
        self.results.setReadOnly(True)
        self.results.setMinimumHeight(120)
        layout.addRow(self.results)
        self.show_results()

    def apply(self):
        for name, box in self.numbers.items():
            value = fields.value(box)
            if abs(_value(self.obj, name) - value) > 1e-12:
                setattr(self.obj, name, value)
        for name, combo in self.choices.items():
            if getattr(self.obj, name) != combo.currentText():
                setattr(self.obj, name, combo.currentText())

    def recompute(self):
        from sliceform_app import observer, syncing

        self.apply()
        QtGui.QApplication.setOverrideCursor(QtCore.Qt.WaitCursor)
        try:
            with observer.held():
                self.doc.recompute()
                syncing.sync(self.obj)  # inside the panel's transaction
        finally:
            QtGui.QApplication.restoreOverrideCursor()
        self.show_results()

    def show_results(self):
        if self.obj.isValid():
            self.results.setPlainText(self.obj.Report or translate("Sliceform", "Not computed yet: press Recompute."))
        else:
            self.results.setPlainText(translate("Sliceform", "Error: ") + self.obj.getStatusString())

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)

    def accept(self):
        self.recompute()
        self.doc.commitTransaction()
        FreeCADGui.ActiveDocument.resetEdit()
        self._release()
        return True

    def _release(self):
        # The fields die with the panel: no Python reference may outlive them (shiboken
        # would hand a stale one out for a field made later at the same address).
        self.numbers, self.choices = {}, {}

    def reject(self):
        # Back to the document before the panel: properties, results and children. The
        # design of that state is still in memory, so the recompute is quick.
        self.doc.abortTransaction()
        if self.doc.isTouched():
            self.doc.recompute()
        FreeCADGui.ActiveDocument.resetEdit()
        self._release()
        return True

