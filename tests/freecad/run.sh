#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Installs the workbench from BUILD_DIR into a throwaway HOME and runs the FreeCAD tests
# headless, so a test run never touches the user's FreeCAD settings or Mod folder.
set -euo pipefail
build=$(cd "$1" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
home=$(mktemp -d)
trap 'rm -rf "$home"' EXIT
cmake --install "$build" --prefix "$home/.local/share/FreeCAD/Mod/Sliceform" >/dev/null
export HOME="$home" XDG_DATA_HOME="$home/.local/share" XDG_CONFIG_HOME="$home/.config" XDG_CACHE_HOME="$home/.cache"
# -t before -M: the test module lives in this folder, added as a module path.
freecadcmd -t TestSliceform -M "$here"
