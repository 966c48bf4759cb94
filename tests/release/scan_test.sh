#!/usr/bin/env bash
# The release scan (grader/release/scan-release.sh) on a release made by hand from the public
# files: it passes that, and refuses each thing a student release must not hold, naming the
# file: a helper that computes the answer in a public test, a line of the solution, a graders'
# folder, a hidden reference image.
#
#   tests/release/scan_test.sh SOURCE_DIR SCRATCH_DIR
set -uo pipefail
root="$1" scratch="$2"
scan="$root/grader/release/scan-release.sh"
failures=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# A release of the public files only.
fresh() {
  rm -rf "$scratch/release"
  mkdir -p "$scratch/release/tests/support" "$scratch/release/tests/golden"
  cp -r "$root/starter" "$root/framework" "$scratch/release/"
  cp "$root"/tests/*.cpp "$scratch/release/tests/"
  cp "$root"/tests/golden/*.cpp "$root"/tests/golden/*.png "$scratch/release/tests/golden/"
  find "$root/tests/support" -maxdepth 1 -type f  \
    -exec cp {} "$scratch/release/tests/support/" \;
}

# Runs the scan; $1: 0 when it must pass, 1 when it must refuse; $2: what its output must hold.
expect_scan() {
  local want="$1" says="$2" what="$3" out status
  out="$(bash "$scan" "$root" "$scratch/release" 2>&1)"
  status=$?
  if [ "$status" -ne "$want" ]; then
    fail "$what: the scan exited $status, not $want:"$'\n'"$out"
  elif ! grep -qF -- "$says" <<<"$out"; then
    fail "$what: the scan did not say '$says':"$'\n'"$out"
  else
    echo "ok: $what"
  fi
}

fresh
expect_scan 0 "none found" "the public files pass"

fresh
cat >>"$scratch/release/tests/task2_forces_test.cpp" <<'CPP'
namespace a6::test {
Vec2 expectedTotal(const Particle& p, const Environment& env) {
  return p.m * env.gravity - env.drag * p.v;
}
}  // namespace a6::test
CPP
line=$(grep -n 'Vec2 expectedTotal' "$scratch/release/tests/task2_forces_test.cpp" | cut -d: -f1)
expect_scan 1 "tests/task2_forces_test.cpp:$line: a helper that computes the answer" \
  "a helper named expected... in a public test is refused"

fresh
mkdir -p "$scratch/release/tests/support/more"
printf 'inline Vec2 correctForce(const Spring& s,\n                         const Particle& a) {\n  return {};\n}\n' \
  >"$scratch/release/tests/support/more/helpers.h"
expect_scan 1 "tests/support/more/helpers.h:1: a helper that computes the answer" \
  "a helper named correct... anywhere under tests/ is refused"

fresh
printf 'TEST(Task3TimeStepping, Helper) {\n  auto expectedStep = [&](double h) {\n    return h;\n  };\n}\n' \
  >>"$scratch/release/tests/task3_time_stepping_test.cpp"
expect_scan 1 "tests/task3_time_stepping_test.cpp:" "a lambda named expected... is refused too"

fresh
line="$(grep -m1 -E '^[[:space:]]*return .{20,};' "$root/solution/spring.cpp")"
printf 'TEST(Task1Spring, Helper) {\n%s\n}\n' "$line" >>"$scratch/release/tests/task1_spring_test.cpp"
expect_scan 1 "tests/task1_spring_test.cpp:" "a line of the solution pasted into a public test is refused"

fresh
cp "$root/solution/forces.cpp" "$scratch/release/starter/forces.cpp"
expect_scan 1 "starter/forces.cpp:" "the solution's code in the starter is refused"
expect_scan 1 "solution text" "and said to be solution text"

fresh
mkdir -p "$scratch/release/tests/hidden"
expect_scan 1 "tests/hidden is in the release" "a graders' folder is refused"

fresh
hidden_png="$(find "$root/tests/golden/hidden" -name '*.png' | head -n 1)"
if [ -n "$hidden_png" ]; then
  cp "$hidden_png" "$scratch/release/tests/golden/innocent.png"
  expect_scan 1 "tests/golden/innocent.png is a hidden reference image" \
    "a hidden image under another name is refused"
fi

rm -rf "$scratch/release"
[ "$failures" -eq 0 ] || { echo "$failures scan checks failed" >&2; exit 1; }
echo "every scan check passed"
