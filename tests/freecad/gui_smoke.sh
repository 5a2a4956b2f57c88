#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Runs gui_smoke.py, then gui_children.py, each in a fresh FreeCAD GUI under Xvfb, with the
# workbench installed from BUILD_DIR into a throwaway HOME.
# Usage: gui_smoke.sh BUILD_DIR [SCREENSHOT.png]
set -euo pipefail
source "$(dirname "$0")/throwaway_home.sh" "$1"
export QTWEBENGINE_DISABLE_SANDBOX=1 SLICEFORM_SMOKE_RESULT="$home/result.txt"
export SLICEFORM_CHILDREN_RESULT="$home/children.txt"
export SLICEFORM_SMOKE_PNG="${2:-$build/gui_smoke.png}"
run() {  # SCRIPT RESULT_FILE
  timeout 300 xvfb-run -a -s "-screen 0 1280x1024x24" freecad "$here/$1" >"$home/$1.log" 2>&1 || true
  if [[ "$(cat "$2" 2>/dev/null)" != "ok" ]]; then
    echo "GUI test $1 failed:" >&2
    cat "$2" >&2 2>/dev/null || tail -40 "$home/$1.log" >&2
    exit 1
  fi
}
run gui_smoke.py "$SLICEFORM_SMOKE_RESULT"
echo "GUI smoke test passed; screenshot: $SLICEFORM_SMOKE_PNG"
run gui_children.py "$SLICEFORM_CHILDREN_RESULT"
echo "GUI children test passed"
