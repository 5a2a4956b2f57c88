# SPDX-License-Identifier: LGPL-2.1-or-later
"""Task panel to edit a sliceform: the parameters a maker changes most, a Recompute button
and the results. Every change is one undoable transaction; Cancel undoes it."""
import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

# (property, label, minimum, maximum, step, decimals) for the spin boxes
NUMBERS = (
    ("Slices", "Slices per direction", 4, 2048, 8, 0),
    ("Thickness", "Material thickness (mm)", 0.05, 20, 0.05, 2),
    ("Clearance", "Slot clearance (mm)", 0, 5, 0.05, 2),
    ("Kerf", "Cutter kerf (mm)", 0, 2, 0.01, 2),
    ("MinHingeLength", "Shortest hinge (mm)", 0.5, 100, 0.5, 1),
    ("MinSlotEdgeDistance", "Paper beside a slot (mm)", 0.2, 50, 0.5, 1),
    ("TauA", "Cylinder error budget (tauA)", 0.001, 1, 0.01, 3),
    ("Margin", "Sheet margin (mm)", 0, 100, 1, 1),
    ("FoldAngle", "Fold angle (degrees)", 1, 90, 5, 0),
)
CHOICES = (("Scheme", "Scheme"), ("SheetSize", "Sheet"), ("SlotEnd", "Slot ends"))


def _value(obj, name):
    value = getattr(obj, name)
    return float(value.Value) if hasattr(value, "Value") else float(value)


class SliceformTaskPanel:
    def __init__(self, obj):
        self.obj = obj
        self.doc = obj.Document
        self.doc.openTransaction("Edit sliceform")
        self.form = QtGui.QWidget()
        self.form.setWindowTitle("Sliceform")
        layout = QtGui.QFormLayout(self.form)
        self.numbers = {}
        for name, label, low, high, step, decimals in NUMBERS:
            box = QtGui.QSpinBox() if decimals == 0 else QtGui.QDoubleSpinBox()
            if decimals:
                box.setDecimals(decimals)
            box.setRange(low, high)
            box.setSingleStep(step)
            box.setValue(int(_value(obj, name)) if decimals == 0 else _value(obj, name))
            box.setToolTip(obj.getDocumentationOfProperty(name))
            layout.addRow(label, box)
            self.numbers[name] = box
        self.choices = {}
        for name, label in CHOICES:
            combo = QtGui.QComboBox()
            combo.addItems(obj.getEnumerationsOfProperty(name))
            combo.setCurrentIndex(combo.findText(getattr(obj, name)))
            combo.setToolTip(obj.getDocumentationOfProperty(name))
            layout.addRow(label, combo)
            self.choices[name] = combo
        self.button = QtGui.QPushButton("Recompute")
        self.button.clicked.connect(self.recompute)
        layout.addRow(self.button)
        self.results = QtGui.QPlainTextEdit()
        self.results.setReadOnly(True)
        self.results.setMinimumHeight(120)
        layout.addRow(self.results)
        self.show_results()

    def apply(self):
        for name, box in self.numbers.items():
            if abs(_value(self.obj, name) - box.value()) > 1e-12:
                setattr(self.obj, name, box.value())
        for name, combo in self.choices.items():
            if getattr(self.obj, name) != combo.currentText():
                setattr(self.obj, name, combo.currentText())

    def recompute(self):
        self.apply()
        QtGui.QApplication.setOverrideCursor(QtCore.Qt.WaitCursor)
        try:
            self.doc.recompute()
        finally:
            QtGui.QApplication.restoreOverrideCursor()
        self.show_results()

    def show_results(self):
        if self.obj.isValid():
            self.results.setPlainText(self.obj.Report or "Not computed yet: press Recompute.")
        else:
            self.results.setPlainText("Error: " + self.obj.getStatusString())

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)

    def accept(self):
        self.recompute()
        self.doc.commitTransaction()
        FreeCADGui.ActiveDocument.resetEdit()
        return True

    def reject(self):
        self.doc.abortTransaction()
        self.doc.recompute()
        FreeCADGui.ActiveDocument.resetEdit()
        return True

