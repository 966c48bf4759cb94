#!/usr/bin/env bash
# Every C++ file of the checkout (git ls-files: *.cpp, *.h, *.inc) is formatted as the committed
# .clang-format says, by clang-format 14 (Debian 12's, which CI runs; other versions lay some
# lines out differently, so with another version the test is skipped).
#
#   tests/format/format_test.sh SOURCE_DIR
# Exit code: 0 all formatted, 1 some are not (each named, with the command that fixes it),
# 77 skipped (no clang-format 14, or not a git checkout).
set -uo pipefail
root="$1"
cd "$root" || exit 1
format=""
for c in clang-format-14 clang-format; do
  if command -v "$c" >/dev/null && "$c" --version | grep -q 'version 14\.'; then format="$c"; break; fi
done
[ -n "$format" ] || { echo "SKIP: no clang-format 14 (Debian 12's clang-format package)"; exit 77; }
git rev-parse --is-inside-work-tree >/dev/null 2>&1 || { echo "SKIP: not a git checkout"; exit 77; }
mapfile -d '' files < <(git ls-files -z --cached --others --exclude-standard -- '*.cpp' '*.h' '*.inc')
# Many files per clang-format process, on every core (one process per file spent most of the
# time starting): each file that differs is named in a line "FILE:LINE:COL: error: code should
# be clang-formatted". Any other error (a file clang-format cannot read) fails the test too.
present=()
for f in "${files[@]}"; do [ -f "$f" ] && present+=("$f"); done
said=$(printf '%s\0' "${present[@]}" | xargs -0 -n 40 -P "$(nproc)" "$format" --dry-run -Werror 2>&1)
mapfile -t bad < <(sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' \
  <<<"$said" | sort -u)
other=$(grep 'error' <<<"$said" | grep -v 'error: code should be clang-formatted')
if [ -n "$other" ]; then
  printf '%s\n' "$other" | head -20
  echo "FAIL: clang-format could not check every file (above)"
  exit 1
fi
if [ ${#bad[@]} -gt 0 ]; then
  printf 'not formatted: %s\n' "${bad[@]}"
  echo "FAIL: ${#bad[@]} of ${#files[@]} C++ files differ from .clang-format; fix them with:"
  echo "  $format -i ${bad[*]}"
  exit 1
fi
echo "all ${#files[@]} C++ files formatted as .clang-format says ($("$format" --version))"
