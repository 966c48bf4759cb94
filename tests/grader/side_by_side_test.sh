#!/usr/bin/env bash
# A grade depends on the code alone (docs/instructor.md, "Graders side by side").
#
#   side_by_side_test.sh A6_GRADE SOURCE_DIR OUT_DIR MODE [ROUNDS]
#
# MODE side-by-side: ROUNDS rounds of two gradings of the solution, the second started 3 s after
#   the first, inside a mount namespace with a /run/lock of its own (as a chroot or a container
#   has): they cannot see each other's lock files, and must still both get every point.
# MODE under-load: the solution and a correct alternative graded at once beside busy loops four
#   times the machine's cores; both must get every point (no time is asserted).
# MODE killed-once: the solution graded while something outside (the kernel's OOM killer, another
#   program) kills its probes with SIGKILL, three times at random moments: a check that was
#   running is run again, no kill is charged as a crash, and the solution gets every point.
# Every point: every item of results.json passed, and no grader error. Exit 77 (skipped) when not
# root: without root there is no sandbox user and no namespace to share.
set -uo pipefail
grade="$1" root="$2" out="$3" mode="$4" rounds="${5:-3}"
if [ "$(id -u)" != 0 ]; then
  echo "skipped: needs root"
  exit 77
fi
command -v jq >/dev/null || { echo "skipped: no jq (scripts/install-deps.sh installs it)"; exit 77; }
rm -rf "$out" && mkdir -p "$out" && chmod 755 "$out"

# full_marks DIR: every item passed, no grader error; prints why not.
full_marks() {
  local results="$1/results.json"
  if ! jq -e '(.tests | length > 0) and all(.tests[]; .status == "passed")
              and ((.extra_data.errors // []) | length == 0)' "$results" >/dev/null 2>&1; then
    echo "NOT full marks: $1 (score $(jq -r .score "$results" 2>/dev/null))"
    jq -r '.tests[] | select(.status != "passed") | "  \(.name): \(.output[0:300])"' \
      "$results" 2>/dev/null | head -20
    jq -r '(.extra_data.errors // [])[] | "  error: \(.)"' "$results" 2>/dev/null
    return 1
  fi
}

failed=0
case "$mode" in
side-by-side)
  for round in $(seq 1 "$rounds"); do
    "$grade" "$root/solution" --out "$out/$round/host" --quiet >"$out/$round-host.log" 2>&1 &
    host=$!
    sleep 3
    unshare -m -- sh -c 'mount -t tmpfs a6-own-run-lock /run/lock && exec "$@"' sh \
      "$grade" "$root/solution" --out "$out/$round/own-run" --quiet >"$out/$round-own.log" 2>&1
    wait "$host"
    for g in host own-run; do full_marks "$out/$round/$g" || failed=$((failed + 1)); done
    echo "round $round: $(jq -r .score "$out/$round/host/results.json") and" \
      "$(jq -r .score "$out/$round/own-run/results.json")"
  done
  ;;
under-load)
  hogs=$((4 * $(nproc)))
  pids=()
  for _ in $(seq 1 "$hogs"); do
    sh -c 'while :; do :; done' &
    pids+=($!)
  done
  trap 'kill "${pids[@]}" 2>/dev/null' EXIT
  # The alternative: its own files, the solution's for the rest.
  mkdir -p "$out/float_intermediates"
  cp "$root"/solution/*.cpp "$out/float_intermediates/"
  cp "${A6_VARIANTS:?BUILD/variants, set by ctest}"/alternative/float_intermediates/*.cpp \
    "$out/float_intermediates/"
  "$grade" "$root/solution" --out "$out/solution" --quiet >"$out/solution.log" 2>&1 &
  a=$!
  "$grade" "$out/float_intermediates" --out "$out/alternative" --quiet >"$out/alternative.log" 2>&1
  wait "$a"
  echo "beside $hogs busy loops: solution $(jq -r .score "$out/solution/results.json")," \
    "alternative $(jq -r .score "$out/alternative/results.json")"
  for g in solution alternative; do full_marks "$out/$g" || failed=$((failed + 1)); done
  ;;
killed-once)
  "$grade" "$root/solution" --out "$out/killed" >"$out/killed.log" 2>&1 &
  g=$!
  kills=0
  for _ in $(seq 1 1200); do
    kill -0 "$g" 2>/dev/null || break
    pid=$(pgrep -f "^$out/killed/work/(build/)?a6_probe" | head -1)
    if [ -n "$pid" ] && [ "$kills" -lt 3 ]; then
      sleep 0.$((RANDOM % 5))
      kill -KILL "$pid" 2>/dev/null && kills=$((kills + 1))
    fi
    sleep 0.05
  done
  wait "$g"
  [ "$kills" -gt 0 ] || { echo "no probe was found to kill"; failed=1; }
  echo "killed a probe $kills times: score $(jq -r .score "$out/killed/results.json")," \
    "crashes charged: $(jq -r .extra_data.incidents.crashes "$out/killed/results.json")"
  jq -r '.extra_data.notes[]' "$out/killed/results.json"
  jq -e '.extra_data.incidents.crashes == 0' "$out/killed/results.json" >/dev/null ||
    { echo "a kill from outside was charged as a crash"; failed=$((failed + 1)); }
  full_marks "$out/killed" || failed=$((failed + 1))
  ;;
*)
  echo "unknown mode $mode"
  exit 2
  ;;
esac
[ "$failed" = 0 ] && echo "every grading got every point" || echo "$failed gradings lost points"
[ "$failed" = 0 ]
