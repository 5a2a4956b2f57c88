#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Installs the workbench from BUILD_DIR into a throwaway HOME and runs the FreeCAD tests
# headless, so a test run never touches the user's FreeCAD settings or Mod folder.
set -euo pipefail
source "$(dirname "$0")/throwaway_home.sh" "$1"
# -t before -M: the test module lives in this folder, added as a module path.
# The schema test holds the CLI's --help against the parameter schema.
export SLICEFORM_CLI="$build/App/cli/sliceform"
freecadcmd -t TestSliceform -M "$here"
