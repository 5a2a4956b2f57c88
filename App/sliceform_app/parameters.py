# SPDX-License-Identifier: LGPL-2.1-or-later
"""The Sliceform feature's parameters, made from the core's parameter schema
(sliceform_native.parameter_schema(): name, kind, default, range, unit, group, help): the
properties, the core's parameter dict, the task panel's rows. FreeCAD adds only what is its
own: the custom sheet's width and height, and a solid's Size 0 (it keeps its true size; a
mesh, which carries no unit, gets the schema's size)."""

import FreeCAD

QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

_table = []


def schema():
    """The core's schema, one dict per parameter (loaded with the compiled core)."""
    from sliceform_app import native

    return native().parameter_schema()


def spec(key):
    """The schema's entry for a core key ("thickness")."""
    for s in schema():
        if s["key"] == key:
            return s
    raise KeyError(key)


def freecad_type(s):
    """The property type for a schema entry: lengths and angles keep their units; counts and
    unitless numbers carry the schema's range as a constraint."""
    if s["kind"] == "real":
        return {"mm": "App::PropertyLength", "deg": "App::PropertyAngle"}.get(s["unit"], "App::PropertyFloatConstraint")
    return {
        "integer": "App::PropertyIntegerConstraint",
        "bool": "App::PropertyBool",
        "choice": "App::PropertyEnumeration",
        "direction": "App::PropertyVector",
    }[s["kind"]]


# FreeCAD's own: (property, type, group, default, tooltip), after SheetSize.
_SHEET = (
    ("SheetWidth", "App::PropertyLength", "Sheets", 600.0, QT_TRANSLATE_NOOP("App::Property", "Custom sheet width")),
    ("SheetHeight", "App::PropertyLength", "Sheets", 400.0, QT_TRANSLATE_NOOP("App::Property", "Custom sheet height")),
)
# Defaults FreeCAD sets apart from the schema's (see the module's doc).
FREECAD_DEFAULTS = {"Size": 0.0}
# Properties made elsewhere (the feature's own group).
_ELSEWHERE = ("FoldAngle",)


def table():
    """(property, FreeCAD type, group, default, core key, tooltip) per parameter, in the
    schema's order. Enumerations have their choices as default (the first is selected);
    constraint types have (default, min, max, step)."""
    if _table:
        return _table
    rows = []
    for s in schema():
        name = s["property"]
        if not name or name in _ELSEWHERE:
            continue
        kind = freecad_type(s)
        default = FREECAD_DEFAULTS.get(name, s["default"])
        if kind == "App::PropertyEnumeration":
            default = list(s["choices"]) + (["Custom"] if name == "SheetSize" else [])
        elif kind == "App::PropertyIntegerConstraint":
            default = (int(default), int(s["min"]), int(s["max"]), int(s["step"]))
        elif kind == "App::PropertyFloatConstraint":
            default = (float(default), float(s["min"]), float(s["max"]), float(s["step"]))
        rows.append((name, kind, s["group"], default, s["key"], s["help"]))
        if name == "SheetSize":
            rows += [(n, k, g, d, None, tip) for n, k, g, d, tip in _SHEET]
    _table[:] = rows
    return _table


# Read-only results: (property, type, tooltip)
RESULTS = (
    ("PatchCount", "App::PropertyInteger", QT_TRANSLATE_NOOP("App::Property", "Patches in the design")),
    ("Stable", "App::PropertyBool", QT_TRANSLATE_NOOP("App::Property", "The slotted design is rigid apart from the fold (certificate nullity 1)")),
    ("Interlocks", "App::PropertyInteger", QT_TRANSLATE_NOOP("App::Property", "Interlocked loop pairs left: the design cannot be assembled if > 0")),
    ("SmallestSlotEdgeDistance", "App::PropertyLength", QT_TRANSLATE_NOOP("App::Property", "Smallest paper left beside a slot")),
    ("ShortestHinge", "App::PropertyLength", QT_TRANSLATE_NOOP("App::Property", "Shortest holding hinge")),
    ("MinPatchSpacing", "App::PropertyLength",
     QT_TRANSLATE_NOOP("App::Property", "Closest two patches of one family that overlap seen along their normal (0: none do)")),
    ("MinFinger", "App::PropertyLength", QT_TRANSLATE_NOOP("App::Property", "Paper left between their slots on a common partner")),
    ("Buildable", "App::PropertyBool", QT_TRANSLATE_NOOP("App::Property", "The design meets every rule of the fabrication contract")),
    ("VolumeIoU", "App::PropertyFloat", QT_TRANSLATE_NOOP("App::Property", "Volume IoU of the sliceform against the source (1 = perfect)")),
    ("SheetCount", "App::PropertyInteger", QT_TRANSLATE_NOOP("App::Property", "Sheets used by the layout")),
    ("ChosenDirections", "App::PropertyString",
     QT_TRANSLATE_NOOP("App::Property", "With Directions auto: the frame chosen, its U and V, and why it won")),
    ("Report", "App::PropertyString", QT_TRANSLATE_NOOP("App::Property", "Summary of the last recompute")),
)


def core_params(obj):
    """The core's parameter dict from the feature's properties."""
    params = {}
    for name, kind, _group, _default, key, _tip in table():
        if key is None:
            continue
        value = getattr(obj, name)
        if kind == "App::PropertyVector":
            value = (value.x, value.y, value.z)
        elif kind == "App::PropertyLength":
            value = float(value.Value) if hasattr(value, "Value") else float(value)
        params[key] = value
    if obj.SheetSize == "Custom":
        params["sheet"] = "{:g}x{:g}".format(float(obj.SheetWidth.Value), float(obj.SheetHeight.Value))
    return params


# Options of the command line that FreeCAD sets another way (none today).
_OPTION_PROPERTIES = {}


def option_properties():
    """CLI option (without --) -> property name, from the table."""
    out = {s["option"][2:]: s["property"] for s in schema() if s["option"] and s["property"]}
    out.update(_OPTION_PROPERTIES)
    return out


def property_message(text):
    """The core's message in FreeCAD's words: the CLI's options (--sheet, --size, ...) become
    the properties that set them (SheetSize, Size, ...)."""
    import re

    names = option_properties()

    def named(match):
        return names.get(match.group(1), match.group(0))

    return re.sub(r"--([a-z][a-z0-9-]*)", named, text)
