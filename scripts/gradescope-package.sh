#!/usr/bin/env bash
# Builds the Gradescope autograder zip (docs/instructor.md, "Gradescope"):
#
#   scripts/gradescope-package.sh [OUT.zip]     default: out/gradescope/a6_autograder.zip
#
# At the zip's root: setup.sh and run_autograder (from grader/gradescope/), as Gradescope
# requires, and beside them the part of the source tree that grading needs, taken from
# `git ls-files` (tracked files, and untracked ones git does not ignore: never a build folder).
#
# Left out: what grading does not need, and what must not travel. The autograder grades with the
# rubric, the reference physics and the reference images; it never needs solution/, so the
# zip does not carry it (nor the wrong versions and the alternative solution, which are the
# solution with one file changed, nor the grader's own tests, which use the solution). Kept: the
# autograder's secrets, tests/hidden/, tests/golden/ (hidden goldens included) and
# grader/reference/: they are what it grades with.
set -euo pipefail

repo=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$repo/out/gradescope/a6_autograder.zip}
case "$out" in /*) ;; *) out=$PWD/$out ;; esac

die() {
  echo "gradescope-package: $*" >&2
  exit 1
}

# Folders (and files) of the checkout that the zip leaves out, and why.
excluded=(
  solution/           # never: the autograder does not need it, and the zip travels
  tests/wrong/        # the solution with a mistake in one file
  tests/alternative/  # a second complete solution
  tests/grader/       # the grader's own tests: they grade the solution
  tests/reference/    # the reference physics against the solution and the texts
  tests/bench/        # benchmarks (of the solution)
  tests/render/       # the renderer's, the scenes' and the viewer's tests
  tests/scenes/
  tests/viewer/
  tests/release/      # the student release's test
  framework/viewer/   # the interactive viewer (GLFW, ImGui): not built for grading
  grader/gradescope/  # setup.sh and run_autograder: at the zip's root instead
  grader/release/     # the student release's tooling
  docs/               # guides and handout
  .ci/
  out/
)
# Of scripts/, only the package list setup.sh installs from.
kept_scripts=(scripts/install-deps.sh)

command -v zip >/dev/null ||
  die "the 'zip' command is missing: install it with scripts/install-deps.sh (Debian package zip)"
command -v git >/dev/null || die "git is missing: the file list comes from git ls-files"
top=$(git -C "$repo" rev-parse --show-toplevel 2>/dev/null) ||
  die "$repo is not a git checkout: the file list comes from git ls-files"
# A copy inside another checkout would list that checkout's files under it (the build folder's).
[ "$(cd "$top" && pwd -P)" = "$(cd "$repo" && pwd -P)" ] ||
  die "$repo is not a git checkout itself but lies inside $top: the file list comes from git ls-files"
for f in grader/gradescope/setup.sh grader/gradescope/run_autograder "${kept_scripts[@]}"; do
  [ -f "$repo/$f" ] || die "$f is missing from the checkout"
done

keep() {
  local path=$1 prefix
  for prefix in "${excluded[@]}"; do
    [[ $path == "$prefix"* ]] && return 1
  done
  if [[ $path == scripts/* ]]; then
    local s
    for s in "${kept_scripts[@]}"; do [[ $path == "$s" ]] && return 0; done
    return 1
  fi
  return 0
}

stage=$(mktemp -d "${TMPDIR:-/tmp}/a6_gradescope_package.XXXXXX")
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/zip"

# The source tree: what git knows of (tracked, or untracked and not ignored), minus the above.
count=0
while IFS= read -r -d '' path; do
  [ -f "$repo/$path" ] && [ ! -L "$repo/$path" ] || continue  # deleted in the working tree, a link
  keep "$path" || continue
  mkdir -p "$stage/zip/$(dirname "$path")"
  cp -p "$repo/$path" "$stage/zip/$path"
  count=$((count + 1))
done < <(git -C "$repo" ls-files -z --cached --others --exclude-standard | sort -zu)

# Gradescope's two files, at the root.
# toml++ (the rubric's reader), header-only, for the images whose platform has no package of it
# (Ubuntu 22.04, Gradescope's default): this machine's copy, with its licence. setup.sh's build
# uses it only where the platform's package is missing (cmake/A6Toml.cmake).
toml_headers=/usr/include/toml++
toml_licence=/usr/share/doc/libtomlplusplus-dev/copyright
[ -f "$toml_headers/toml.h" ] && [ -f "$toml_licence" ] ||
  die "toml++ is missing here ($toml_headers, $toml_licence): install it with scripts/install-deps.sh (libtomlplusplus-dev)"
mkdir -p "$stage/zip/vendor/tomlplusplus/include"
cp -r "$toml_headers" "$stage/zip/vendor/tomlplusplus/include/"
cp "$toml_licence" "$stage/zip/vendor/tomlplusplus/LICENSE"
{
  echo "toml++ $(dpkg-query -W -f='${Version}' libtomlplusplus-dev 2>/dev/null || echo '(version unknown)')," \
    "header-only, copied from $toml_headers of the machine that made this zip"
  echo "(Debian's libtomlplusplus-dev; upstream https://github.com/marzer/tomlplusplus; MIT licence: LICENSE)"
} >"$stage/zip/vendor/tomlplusplus/README"

install -m 0755 "$repo/grader/gradescope/setup.sh" "$stage/zip/setup.sh"
install -m 0755 "$repo/grader/gradescope/run_autograder" "$stage/zip/run_autograder"

# Which checkout the zip was made from (run_autograder prints it with every grading).
{
  echo "Assignment 6 autograder, packaged $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "from commit $(git -C "$repo" describe --always --dirty 2>/dev/null || echo unknown)"
} >"$stage/zip/autograder_version.txt"

# Nothing of the solution may be in it (scripts/ and CMake may change; this may not).
[ ! -e "$stage/zip/solution" ] || die "solution/ ended up in the package"

mkdir -p "$(dirname "$out")"
(cd "$stage/zip" && zip -q -r -X "$stage/package.zip" .)
mv -f "$stage/package.zip" "$out"

size=$(du -k "$out" | cut -f1)
echo "gradescope-package: wrote $out ($((count + 3)) files, ${size} KiB)"
echo "gradescope-package: upload it on Gradescope (Configure Autograder), base image Ubuntu 22.04 (the default) or 24.04:"
echo "gradescope-package: see docs/instructor.md, \"Gradescope\""
