#!/bin/sh
# SPDX-License-Identifier: LGPL-2.1-or-later
# Runs `sliceform design MODEL -o DIR` and checks the report independently with
# check_report.py (rigidity, collisions, real hinges, interlocks, split patches).
# Usage: design_check.sh SLICEFORM MODEL CHECK_REPORT
set -eu
sliceform=$1 model=$2 checker=$3
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$sliceform" design "$model" -o "$out"
for f in report.json timings.json sheets.pdf sheets.png sheet-1.svg sheet-1.dxf \
  assembly.step assembly.brep assembly.glb assembly.png; do
  test -s "$out/$f" || { echo "missing $f"; exit 1; }
done
/usr/bin/python3 "$checker" "$out/report.json"
