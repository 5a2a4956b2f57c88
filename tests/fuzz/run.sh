#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Usage: run.sh BUILD_DIR SECONDS
# Runs each fuzz target of BUILD_DIR (configured with SLICEFORM_FUZZ=ON) for SECONDS over
# its corpus, one after the other. Fails on any finding; its input and log are kept in
# the folder printed. New inputs go to a scratch copy: the corpus in the tree stays small.
set -euo pipefail
build=$(cd "$1" && pwd)
seconds=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/sliceform-fuzz.XXXXXX")
status=0
for format in stl obj off; do
  mkdir -p "$work/$format" "$work/tmp"
  # -timeout: an input taking longer is a finding (a hang); -rss_limit_mb: so is a file
  # that makes a reader allocate more than that. TMPDIR: the target's input file (left
  # behind by a crash) and the readers' temporary copies stay in the scratch folder.
  if TMPDIR="$work/tmp" "$build/tests/fuzz/fuzz_$format" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -dict="$here/$format.dict" -artifact_prefix="$work/$format/" -print_final_stats=1 \
      "$work/$format" "$here/corpus/$format" >"$work/$format.log" 2>&1; then
    echo "fuzz_$format: $(grep -m1 'stat::number_of_executed_units' "$work/$format.log" | awk '{print $2}') runs, no findings"
  else
    echo "fuzz_$format: FINDING (log and input in $work)"
    tail -n 40 "$work/$format.log"
    status=1
  fi
done
[[ $status -eq 0 ]] && rm -rf "$work"
exit $status
