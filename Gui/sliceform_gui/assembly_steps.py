# SPDX-License-Identifier: LGPL-2.1-or-later
"""Assembly steps: a display mode over a sliceform's patches. It shows the patches of the
first steps only, the newest in orange, and says which partners its slots go onto; Next and
Previous move through the assembly order. It changes nothing in the document: only the
patches' visibility and colour, put back when the panel closes."""
import json

import FreeCAD
import FreeCADGui

from sliceform_app import assembly_steps, lookup

translate = FreeCAD.Qt.translate

# The new patch's colour in the 3D view: orange, more saturated than the booklet's #E8603C.
# Patches stand on their planes, and one turned from the light is drawn at about half its
# colour: the booklet's orange then came out a dull brown (145, 71, 51 on FreeCAD 1.0) that
# a reader, and the GUI test's orange count, could miss.
HIGHLIGHT = (1.0, 0.33, 0.0)
# ... and it glows: half of it emitted, so a patch turned from the light stays orange, not
# the dark brown (165, 65, 20) FreeCAD 1.0 drew one time in three in the GUI test.
GLOW = tuple(0.5 * c for c in HIGHLIGHT)


def _material(view):
    """The shape's material: FreeCAD 1.0's ShapeAppearance (one per face, the first for
    all when it is uniform) or 0.20's ShapeMaterial. None if the view has neither."""
    if hasattr(view, "ShapeAppearance"):
        return tuple(view.ShapeAppearance)
    return getattr(view, "ShapeMaterial", None)


def _set_material(view, material):
    if hasattr(view, "ShapeAppearance"):
        view.ShapeAppearance = material
    elif material is not None:
        view.ShapeMaterial = material


def _glowing(view, on):
    """The view's material with the glow on, or off (no emission)."""
    def lit(m):
        m.EmissiveColor = GLOW if on else (0.0, 0.0, 0.0)
        return m

    material = _material(view)
    if isinstance(material, tuple):
        return tuple(lit(m) for m in material)
    return None if material is None else lit(material)

current = None  # the open panel, for the GUI test


class AssemblyStepsPanel:
    def __init__(self, sliceform):
        from PySide import QtGui

        global current
        self.obj = sliceform
        report = json.loads(sliceform.Proxy.report_json(sliceform))
        self.steps = assembly_steps.steps(report)
        self.patches = {p.PatchId: p for p in lookup.patches_of(sliceform)}
        shown = [sliceform] + list(self.patches.values())
        self.saved = {o.Name: (o.ViewObject.Visibility, getattr(o.ViewObject, "ShapeColor", None)) for o in shown}
        self.colour = {p.PatchId: p.ViewObject.ShapeColor for p in self.patches.values()}
        # The whole material (emission included), put back last when the panel closes.
        self.materials = {p.Name: _material(p.ViewObject) for p in self.patches.values()}
        # Filled while stepping: in wireframe (a 2D object's default, and older documents')
        # the highlight colour, a face colour, would not show.
        self.modes = {p.Name: p.ViewObject.DisplayMode for p in self.patches.values()}
        for p in self.patches.values():
            if "Flat Lines" in p.ViewObject.listDisplayModes():
                p.ViewObject.DisplayMode = "Flat Lines"
        self.form = QtGui.QWidget()
        self.form.setWindowTitle(translate("Sliceform", "Assembly steps"))
        layout = QtGui.QVBoxLayout(self.form)
        self.label = QtGui.QLabel()
        self.label.setWordWrap(True)
        layout.addWidget(self.label)
        row = QtGui.QHBoxLayout()
        self.previous = QtGui.QPushButton(translate("Sliceform", "Previous"))
        self.next = QtGui.QPushButton(translate("Sliceform", "Next"))
        row.addWidget(self.previous)
        row.addWidget(self.next)
        layout.addLayout(row)
        self.previous.clicked.connect(lambda: self.go(self.step - 1))
        self.next.clicked.connect(lambda: self.go(self.step + 1))
        self.step = 0
        sliceform.ViewObject.Visibility = False
        self.go(1)
        current = self

    def go(self, step):
        """Shows the patches of steps 1..step, the last one highlighted."""
        self.step = max(1, min(step, len(self.steps)))
        for k, (pid, _text) in enumerate(self.steps):
            patch = self.patches.get(pid)
            if patch is None:
                continue
            patch.ViewObject.Visibility = k < self.step
            new = k == self.step - 1
            patch.ViewObject.ShapeColor = HIGHLIGHT if new else self.colour[pid]
            _set_material(patch.ViewObject, _glowing(patch.ViewObject, new))
        self.label.setText(self.steps[self.step - 1][1] if self.steps else "")
        self.previous.setEnabled(self.step > 1)
        self.next.setEnabled(self.step < len(self.steps))
        FreeCADGui.updateGui()

    def restore(self):
        global current
        for name, (visible, colour) in self.saved.items():
            o = self.obj.Document.getObject(name)
            if o is None:
                continue
            o.ViewObject.Visibility = visible
            if colour is not None:
                o.ViewObject.ShapeColor = colour
            if name in self.modes and o.ViewObject.DisplayMode != self.modes[name]:
                o.ViewObject.DisplayMode = self.modes[name]
            if name in self.materials:
                _set_material(o.ViewObject, self.materials[name])
        current = None

    def getStandardButtons(self):
        from PySide import QtGui

        return int(QtGui.QDialogButtonBox.Close)

    def reject(self):
        self.restore()
        FreeCADGui.Control.closeDialog()
        return True

    def accept(self):
        return self.reject()
