# SPDX-License-Identifier: LGPL-2.1-or-later
"""The number fields the task panel and the preferences page show, from the core's
parameter schema: lengths and angles in FreeCAD's own quantity field, counts and plain
numbers in Qt spin boxes."""
import FreeCADGui
from PySide import QtGui

SUFFIX = {"mm": " mm", "s": " s", "deg": "\u00b0"}
# Units FreeCAD's quantity fields know: a length or an angle is typed in any unit of its
# kind ("0.02 in", "1/64 in", "0.5 rad") and shown in the user's unit schema.
QUANTITY = {"mm": "mm", "deg": "deg"}


def decimals(spec):
    """Decimals a plain field shows: none for a count, else as many as the step has."""
    if spec["kind"] == "integer":
        return 0
    return max(1, len(repr(float(spec["step"])).split(".")[1].rstrip("0")))


def quantity_field(parent, unit, low, high, step, value):
    """FreeCAD's own quantity field (Gui::QuantitySpinBox), as its property editor uses;
    owned by `parent` (a field the loader made without one is deleted with the loader).
    None where shiboken hands out the wrapper of an earlier, deleted widget at the same
    address, which a Python name still holds (the main window's findChildren keeps every
    widget it returned)."""
    box = FreeCADGui.UiLoader().createWidget("Gui::QuantitySpinBox", parent)
    try:
        box.setProperty("unit", unit)
    except RuntimeError:
        return None
    box.setProperty("minimum", low)
    box.setProperty("maximum", high)
    box.setProperty("singleStep", step)
    box.setProperty("rawValue", value)
    return box


def number_field(low, high, step, places, suffix, value):
    """A plain spin box: a count (places 0) or a number with its suffix."""
    if places == 0:
        box = QtGui.QSpinBox()
        low, high, step, value = int(low), int(high), int(step), int(value)
    else:
        box = QtGui.QDoubleSpinBox()
        box.setDecimals(places)
    box.setRange(low, high)
    box.setSingleStep(step)
    box.setSuffix(suffix)
    box.setValue(value)
    return box


def field(parent, spec, value):
    """The field for a schema row (a dict with kind, unit, min, max, step) holding `value`."""
    unit = QUANTITY.get(spec["unit"])
    box = quantity_field(parent, unit, spec["min"], spec["max"], spec["step"], value) if unit else None
    if box is None:
        box = number_field(spec["min"], spec["max"], spec["step"], decimals(spec), SUFFIX.get(spec["unit"], ""), value)
    return box


def value(box):
    """A field's number, in the property's own unit (mm, degrees) for a quantity field."""
    raw = box.property("rawValue")
    return float(raw) if raw is not None else box.value()


def set_value(box, number):
    if box.property("rawValue") is not None:
        box.setProperty("rawValue", float(number))
    elif isinstance(box, QtGui.QSpinBox):
        box.setValue(int(number))
    else:
        box.setValue(float(number))
