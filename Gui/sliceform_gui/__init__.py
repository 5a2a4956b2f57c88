# SPDX-License-Identifier: LGPL-2.1-or-later
"""Sliceform, FreeCAD GUI side: commands, task panels, view providers. Importing the
package is cheap; commands are loaded when the workbench is first activated."""
import os

RESOURCES = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "Resources")


def icon_path(name):
    return os.path.join(RESOURCES, "icons", name)


def translations_path():
    return os.path.join(RESOURCES, "translations")
