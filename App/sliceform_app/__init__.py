# SPDX-License-Identifier: LGPL-2.1-or-later
"""Sliceform, FreeCAD side without GUI: the compiled core, shape conversion, features.

Importing this package is cheap and never fails: the compiled module is loaded by
native() on first use, with a clear message if it is missing.
"""
import os

ADDON_DIR = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


class NativeModuleMissing(ImportError):
    """The compiled core (sliceform_native) is not installed or does not load."""


def native():
    """The compiled core module, sliceform_native."""
    try:
        import sliceform_native
    except ImportError as e:
        raise NativeModuleMissing(
            "Sliceform's compiled core (sliceform_native) could not be loaded: {}. "
            "On Debian 12 or 13 install the freecad-sliceform package instead; elsewhere "
            "build and install it as the README's Install section says: it must be built "
            "for FreeCAD's own Python.".format(e)
        ) from e
    return sliceform_native
