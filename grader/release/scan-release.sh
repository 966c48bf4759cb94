#!/usr/bin/env bash
# Scans a student release for graders' material:
#
#   grader/release/scan-release.sh ROOT DEST
#
# ROOT is the instructors' checkout, DEST the release. Fails (exit 1), naming file and line, when
# DEST holds
#   - a graders' path: solution/, tests/hidden/, tests/golden/hidden/, reference_models.inc;
#   - a line of code of the solution, the hidden checks or the reference models: every line of
#     those files that is not a comment, is at least 25 characters long (shorter ones, such as
#     "return f;", are in any C++ file) and is not also in the public code (starter/,
#     framework/, the public tests), compared with leading and trailing blanks trimmed;
#   - a hidden reference image, by content (sha256), under any name.
set -euo pipefail
root="$1" dest="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
found=0

for path in solution tests/hidden tests/golden/hidden tests/support/reference_models.inc; do
  if [ -e "$dest/$path" ]; then
    echo "scan: $path is in the release" >&2
    found=1
  fi
done
while IFS= read -r -d '' file; do
  echo "scan: ${file#"$dest"/} is in the release (a graders' file name)" >&2
  found=1
done < <(find "$dest" \( -name reference_models.inc -o -name hidden_test.cpp \) -print0)

trimmed() { sed -e 's/^[[:space:]]*//' -e 's/[[:space:]]*$//' "$@"; }

# The secret lines, less the public ones.
shopt -s nullglob
secret_files=("$root"/solution/*.cpp "$root"/tests/hidden/* "$root"/tests/support/reference_models.inc)
public_files=("$root"/starter/* "$root"/tests/*.cpp "$root"/tests/support/*.h "$root"/tests/support/*.cpp
              "$root"/tests/golden/*.cpp)
trimmed "${secret_files[@]}" | grep -v -e '^//' -e '^/\*' -e '^\*' | awk 'length($0) >= 25' |
  sort -u >"$work/secret"
{ trimmed "${public_files[@]}"; find "$root/framework" -type f \( -name '*.h' -o -name '*.cpp' \) \
    -exec sed -e 's/^[[:space:]]*//' -e 's/[[:space:]]*$//' {} +; } | sort -u >"$work/public"
comm -23 "$work/secret" "$work/public" >"$work/lines"
if [ ! -s "$work/lines" ]; then
  echo "scan: no secret lines to look for (is $root the instructors' checkout?)" >&2
  exit 1
fi

while IFS= read -r -d '' file; do
  grep -Iq . "$file" 2>/dev/null || continue  # binary
  if hits="$(trimmed "$file" | grep -nFx -f "$work/lines")"; then
    while IFS= read -r hit; do
      echo "scan: ${file#"$dest"/}:${hit%%:*}: solution text: ${hit#*:}" >&2
    done <<<"$hits"
    found=1
  fi
done < <(find "$dest" -type f -print0)

# Hidden images, by content.
for png in "$root"/tests/golden/hidden/*.png; do
  sha256sum "$png" | cut -d' ' -f1
done | sort -u >"$work/hidden_png"
if [ -s "$work/hidden_png" ]; then
  while IFS= read -r -d '' png; do
    if grep -qx "$(sha256sum "$png" | cut -d' ' -f1)" "$work/hidden_png"; then
      echo "scan: ${png#"$dest"/} is a hidden reference image" >&2
      found=1
    fi
  done < <(find "$dest" -type f -name '*.png' -print0)
fi

if [ "$found" -eq 0 ]; then
  echo "scan: $(wc -l <"$work/lines") secret lines and $(wc -l <"$work/hidden_png") hidden images looked for in $(find "$dest" -type f | wc -l) files: none found"
fi
exit "$found"
