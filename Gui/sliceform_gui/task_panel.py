# SPDX-License-Identifier: LGPL-2.1-or-later
"""Task panel to edit a sliceform: the parameters a maker changes most, a Recompute button
and the results. The panel is one transaction: OK commits it as one Undo step, Cancel
aborts it, which gives back exactly the document from before the panel opened (the
children a trial Recompute added or removed included)."""
import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui


QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP
translate = FreeCAD.Qt.translate


# (property, label, minimum, maximum, step, decimals) for the spin boxes
NUMBERS = (
    ("Slices", QT_TRANSLATE_NOOP("Sliceform", "Slices per direction"), 4, 2048, 8, 0),
    ("Size", QT_TRANSLATE_NOOP("Sliceform", "Size: longest side (mm, 0 keeps the source's)"), 0, 100000, 10, 1),
    ("Thickness", QT_TRANSLATE_NOOP("Sliceform", "Material thickness (mm)"), 0.05, 20, 0.05, 2),
    ("Clearance", QT_TRANSLATE_NOOP("Sliceform", "Slot clearance (mm)"), 0, 5, 0.05, 2),
    ("Kerf", QT_TRANSLATE_NOOP("Sliceform", "Cutter kerf (mm)"), 0, 2, 0.01, 2),
    ("MinHingeLength", QT_TRANSLATE_NOOP("Sliceform", "Shortest hinge (mm)"), 0.5, 100, 0.5, 1),
    ("MinSlotEdgeDistance", QT_TRANSLATE_NOOP("Sliceform", "Paper beside a slot (mm)"), 0.2, 50, 0.5, 1),
    ("TauA", QT_TRANSLATE_NOOP("Sliceform", "Cylinder error budget (tauA)"), 0.001, 1, 0.01, 3),
    ("Margin", QT_TRANSLATE_NOOP("Sliceform", "Sheet margin (mm)"), 0, 100, 1, 1),
    ("Spacing", QT_TRANSLATE_NOOP("Sliceform", "Space between patches (mm)"), 0, 100, 1, 1),
    ("SheetWidth", QT_TRANSLATE_NOOP("Sliceform", "Custom sheet width (mm)"), 10, 10000, 10, 1),
    ("SheetHeight", QT_TRANSLATE_NOOP("Sliceform", "Custom sheet height (mm)"), 10, 10000, 10, 1),
    ("FoldAngle", QT_TRANSLATE_NOOP("Sliceform", "Fold angle (degrees)"), 1, 90, 5, 0),
)
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
            layout.addRow(translate("Sliceform", label), box)
            self.numbers[name] = box
        self.choices = {}
        for name, label in CHOICES:
            combo = QtGui.QComboBox()
            combo.addItems(obj.getEnumerationsOfProperty(name))
            combo.setCurrentIndex(combo.findText(getattr(obj, name)))
            combo.setToolTip(obj.getDocumentationOfProperty(name))
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
            if abs(_value(self.obj, name) - box.value()) > 1e-12:
                setattr(self.obj, name, box.value())
        for name, combo in self.choices.items():
            if getattr(self.obj, name) != combo.currentText():
                setattr(self.obj, name, combo.currentText())

    def recompute(self):
        from sliceform_app import children

        self.apply()
        QtGui.QApplication.setOverrideCursor(QtCore.Qt.WaitCursor)
        try:
            with children.held():
                self.doc.recompute()
                children.sync(self.obj)  # inside the panel's transaction
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
        return True

    def reject(self):
        # Back to the document before the panel: properties, results and children. The
        # design of that state is still in memory, so the recompute is quick.
        self.doc.abortTransaction()
        if self.doc.isTouched():
            self.doc.recompute()
        FreeCADGui.ActiveDocument.resetEdit()
        return True

