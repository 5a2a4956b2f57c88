# SPDX-License-Identifier: LGPL-2.1-or-later
"""The Sliceform feature's parameters: one table that makes the properties, reads them into
the core's parameter dict, and gives the preferences page its defaults. Names on the core
side are the CLI's (`sliceform design --help`)."""

# (property, FreeCAD type, group, default, core key, tooltip)
# Enumerations have their choices as default (the first is selected).
PARAMETERS = (
    ("Directions", "App::PropertyEnumeration", "Slicing", ["given", "auto"], "directions",
     "auto (new features): slicing directions chosen for the model (its principal and the file's "
     "axes, each up, the families turned about it; ChosenDirections says which); given: "
     "UDirection and VDirection"),
    ("UDirection", "App::PropertyVector", "Slicing", (1.0, 0.0, 0.0), "u",
     "Normal of the U family of patches (global coordinates)"),
    ("VDirection", "App::PropertyVector", "Slicing", (0.0, 1.0, 0.0), "v",
     "Normal of the V family; must be orthogonal to U. W = U x V is 'up'"),
    ("Slices", "App::PropertyInteger", "Slicing", 128, "slices", "Slices per direction"),
    ("Interval", "App::PropertyLength", "Slicing", 0.0, "interval",
     "Distance between slices; 0 uses Slices instead"),
    ("TauA", "App::PropertyFloat", "Slicing", 0.1, "tau_a",
     "Cylinder error budget, relative to each part's volume (paper: tauA)"),
    ("TauM", "App::PropertyFloat", "Slicing", 0.03, "tau_m", "Reeb branch merge threshold (paper: tauM)"),
    ("Scheme", "App::PropertyEnumeration", "Slicing", ["both", "u", "v"], "scheme",
     "Both families, or one dominant direction"),
    ("Size", "App::PropertyLength", "Slicing", 0.0, "size",
     "Scale the source so its longest side is this long; 0 keeps its size"),
    ("MinHingeLength", "App::PropertyLength", "Hinges", 4.0, "min_hinge_length",
     "A hinge must be this long to carry load"),
    ("MinSlotEdgeDistance", "App::PropertyLength", "Hinges", 2.0, "min_slot_edge_distance",
     "Paper to keep on each side of a slot"),
    ("MaxSpacing", "App::PropertyLength", "Hinges", 0.0, "max_spacing",
     "Add patches in long cylinders so none is farther apart; 0 is off"),
    ("MinSpacing", "App::PropertyLength", "Hinges", 0.0, "min_spacing",
     "Least distance between two patches of one family that overlap seen along their normal, "
     "so paper is left between their slots; 0 is slot width + MinSlotEdgeDistance"),
    ("TimeLimit", "App::PropertyFloat", "Slicing", 60.0, "time_limit",
     "Seconds the design may take before its searches stop with the best found; 0 is no limit"),
    ("Thickness", "App::PropertyLength", "Material", 0.3, "thickness",
     "Material thickness (0.3 mm card, 3 mm plywood)"),
    ("Clearance", "App::PropertyLength", "Material", 0.2, "clearance", "Added to the thickness for the slot width"),
    ("Kerf", "App::PropertyLength", "Material", 0.0, "kerf",
     "Width the cutter removes; cut paths are moved out by half"),
    ("SlotEnd", "App::PropertyEnumeration", "Material", ["square", "round"], "slot_end", "Closed slot ends"),
    ("USlots", "App::PropertyEnumeration", "Material", ["up", "down"], "u_slots",
     "Which way U-patches are slotted first (V the other way)"),
    ("SheetSize", "App::PropertyEnumeration", "Sheets", ["A4", "A3", "Letter", "Custom"], "sheet",
     "Sheet size for the layout; Custom uses SheetWidth x SheetHeight"),
    ("SheetWidth", "App::PropertyLength", "Sheets", 600.0, None, "Custom sheet width"),
    ("SheetHeight", "App::PropertyLength", "Sheets", 400.0, None, "Custom sheet height"),
    ("Margin", "App::PropertyLength", "Sheets", 10.0, "margin", "Kept clear along every sheet edge"),
    ("Spacing", "App::PropertyLength", "Sheets", 3.0, "spacing", "Between patches on a sheet"),
    ("Rotate", "App::PropertyBool", "Sheets", True, "rotate", "Patches may be turned by quarters to nest better"),
)

# Read-only results: (property, type, tooltip)
RESULTS = (
    ("PatchCount", "App::PropertyInteger", "Patches in the design"),
    ("Stable", "App::PropertyBool", "The slotted design is rigid apart from the fold (certificate nullity 1)"),
    ("Interlocks", "App::PropertyInteger", "Interlocked loop pairs left: the design cannot be assembled if > 0"),
    ("SmallestSlotEdgeDistance", "App::PropertyLength", "Smallest paper left beside a slot"),
    ("ShortestHinge", "App::PropertyLength", "Shortest holding hinge"),
    ("MinPatchSpacing", "App::PropertyLength",
     "Closest two patches of one family that overlap seen along their normal (0: none do)"),
    ("MinFinger", "App::PropertyLength", "Paper left between their slots on a common partner"),
    ("Buildable", "App::PropertyBool", "The design meets every rule of the fabrication contract"),
    ("VolumeIoU", "App::PropertyFloat", "Volume IoU of the sliceform against the source (1 = perfect)"),
    ("SheetCount", "App::PropertyInteger", "Sheets used by the layout"),
    ("ChosenDirections", "App::PropertyString",
     "With Directions auto: the frame chosen, its U and V, and why it won"),
    ("Report", "App::PropertyString", "Summary of the last recompute"),
)


def core_params(obj):
    """The core's parameter dict from the feature's properties."""
    params = {}
    for name, kind, _group, _default, key, _tip in PARAMETERS:
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


# Options of the command line that have no property of their own, by what they are here.
_OPTION_PROPERTIES = {"sheet": "SheetSize", "u": "UDirection", "v": "VDirection", "no-rotate": "Rotate"}


def option_properties():
    """CLI option (without --) -> property name, from the table."""
    out = {key.replace("_", "-"): name for name, _kind, _group, _default, key, _tip in PARAMETERS if key}
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
