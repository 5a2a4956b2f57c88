#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Runs gui_smoke.py in the FreeCAD GUI under Xvfb, with the workbench installed from
# BUILD_DIR into a throwaway HOME. Usage: gui_smoke.sh BUILD_DIR [SCREENSHOT.png]
set -euo pipefail
source "$(dirname "$0")/throwaway_home.sh" "$1"
export QTWEBENGINE_DISABLE_SANDBOX=1 SLICEFORM_SMOKE_RESULT="$home/result.txt"
export SLICEFORM_SMOKE_PNG="${2:-$build/gui_smoke.png}"
timeout 300 xvfb-run -a -s "-screen 0 1280x1024x24" freecad "$here/gui_smoke.py" >"$home/freecad.log" 2>&1 || true
if [[ "$(cat "$SLICEFORM_SMOKE_RESULT" 2>/dev/null)" != "ok" ]]; then
  echo "GUI smoke test failed:" >&2
  cat "$SLICEFORM_SMOKE_RESULT" >&2 2>/dev/null || tail -40 "$home/freecad.log" >&2
  exit 1
fi
echo "GUI smoke test passed; screenshot: $SLICEFORM_SMOKE_PNG"
