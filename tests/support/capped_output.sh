#!/usr/bin/env bash
# Runs one test's command for ctest with its whole output kept in a log file. The output is
# printed whole when the command passes (ctest shows it only with -V, and
# PASS_REGULAR_EXPRESSION reads it) or when it is short; a failing command's long output is cut
# to LIMIT lines (the first two thirds and the last third), with the log's name where the cut is.
#
#   capped_output.sh LOG LIMIT COMMAND [ARG...]        (exits with COMMAND's status)
log=$1 limit=$2
shift 2
mkdir -p "$(dirname "$log")"
"$@" >"$log" 2>&1
status=$?
lines=$(wc -l <"$log")
if [ "$status" -eq 0 ] || [ "$lines" -le "$limit" ]; then
  cat "$log"
else
  head -n $((limit * 2 / 3)) "$log"
  echo "[... $((lines - limit)) lines left out here; the whole output: $log ...]"
  tail -n $((limit / 3)) "$log"
fi
exit "$status"
