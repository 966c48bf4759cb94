#!/usr/bin/env bash
# The files compiled together in a bundle (cmake/A6FastBuild.cmake, a6_bundled) cannot meet: in
# a bundle, what one file declares at namespace scope is seen by the files after it, so that a
# helper of one could become what another file's call finds. Fails where that could happen
# (meetings, below).
# Measured by Universal Ctags, as function_size_test.sh does.
#
#   tests/format/bundles_test.sh BUNDLE_LIST WORK_DIR
# BUNDLE_LIST: a6_bundles.txt of the build folder (one bundle per line). Exit code: 0 none meet,
# 1 some do (each named), or the measure failed its canary, 77 skipped (no Universal Ctags).
set -uo pipefail
list="$1" work="$2"
source "$(dirname "$0")/find_ctags.sh"  # $ctags, or skipped

# meetings FILE...: how the files of one bundle could meet, a line each:
#   - a name of one file's own (its anonymous namespace's, an unscoped enum's there, a static
#     function or variable), or a macro, that is a word of another file (the other's unqualified
#     lookup could find it; comments count too: a name used nowhere else cannot be a mistake);
#   - an operator of one file's own (it has no word to look for);
#   - `using` at namespace scope, in a namespace another file of the bundle opens too;
#   - an #include inside an anonymous namespace (what it declares, ctags does not see).
# Anonymous namespaces are one per translation unit: their ctags names (__anonN) are one here.
meetings() {
  local name file other
  "$ctags" --languages=C++ --language-force=C++ --kinds-C++=cdefgnstuvNU --extras=+r \
    --fields=+KsZf -o - "$@" 2>/dev/null |
    awk -F'\t' '{
      kind = $4; scope = "-"; holder = "namespace"; static = 0  # (a class member is no lookup outside it)
      for (i = 5; i <= NF; i++) {
        if ($i ~ /^scope:/) {
          scope = substr($i, 7); holder = scope; sub(/:.*/, "", holder); sub(/^[a-z]+:/, "", scope)
        } else if ($i == "file:") static = 1
      }
      gsub(/__anon[0-9a-f]+/, "(anonymous)", scope)
      private = (holder == "namespace" || holder == "enum") && scope ~ /\(anonymous\)/
      private = private || (static && holder == "namespace" && (kind == "function" || kind == "variable"))
      if (kind == "namespace") {
        ns = (scope == "-" ? "" : scope "::") $1
        gsub(/__anon[0-9a-f]+/, "(anonymous)", ns)
        if (index(opened[ns], " " $2 " ") == 0) opened[ns] = opened[ns] " " $2 " "
      } else if ((kind == "using" || kind == "name") && holder == "namespace") {
        imports[++n] = scope "\t" $2
      } else if (private && $1 ~ /^operator/) {
        print "operator\t" $1 "\t" $2
      } else if (kind == "macro" || private) {
        print "word\t" $1 "\t" $2
      }
    }
    END {
      for (i = 1; i <= n; i++) {
        split(imports[i], a, "\t")
        if (a[1] == "-" || a[1] ~ /\(anonymous\)/ || opened[a[1]] != " " a[2] " ")
          print "import\t" a[1] "\t" a[2]
      }
    }' | sort -u |
    while IFS=$'\t' read -r what name file; do
      case "$what" in
        import) echo "$file imports names into $name, which another file of the bundle shares" ;;
        operator) echo "$name, of $(basename "$file"): an operator no other file may see (no word to look for)" ;;
        word)
          for other in "$@"; do
            [ "$other" != "$file" ] && grep -qw -- "$name" "$other" &&
              echo "$name, of $(basename "$file")'s own names, is a word of $(basename "$other")"
          done ;;
      esac
    done
  # What a file includes inside its anonymous namespace, ctags does not see: none may.
  for file in "$@"; do
    awk -v f="$(basename "$file")" '/^namespace \{$/ { ++depth } /^\}  \/\/ namespace$/ { --depth }
      depth > 0 && /^[ \t]*#[ \t]*include/ { print f ": includes inside its anonymous namespace: " $0 }' "$file"
  done
}

# The canary: two files that share a helper in an anonymous namespace and import into a shared
# namespace must meet; two that keep to namespaces of their own must not.
mkdir -p "$work" || exit 1
printf 'namespace a { namespace { int helper(int x) { return x; } } }\n' >"$work/one.cpp"
printf 'namespace a { using b::c; namespace { int helper(double x) { return 2; } } }\n' >"$work/two.cpp"
printf 'namespace a::one { int helper(int x) { return x; } using b::c; }\n' >"$work/own1.cpp"
printf 'namespace a::two { int helper(double x) { return 2; } }\n' >"$work/own2.cpp"
met=$(meetings "$work/one.cpp" "$work/two.cpp")
grep -q '^helper, ' <<<"$met" && grep -q 'imports names into a,' <<<"$met" &&
  [ -z "$(meetings "$work/own1.cpp" "$work/own2.cpp")" ] ||
  { echo "FAIL: the measure is broken; the canary gave:"; echo "${met:-(nothing)}"; exit 1; }

bundles=0 bad=0
while IFS= read -r bundle; do
  [ -n "$bundle" ] || continue
  [ -f "$bundle" ] || { echo "FAIL: no bundle $bundle"; bad=1; continue; }
  dir=$(dirname "$bundle")
  mapfile -t files < <(sed -n 's/^#include "\(.*\)"$/\1/p' "$bundle" | while IFS= read -r f; do realpath "$dir/$f"; done)
  [ ${#files[@]} -gt 0 ] || { echo "FAIL: $bundle includes no file"; bad=1; continue; }
  bundles=$((bundles + 1))
  met=$(meetings "${files[@]}")
  if [ -n "$met" ]; then
    echo "FAIL: in $(basename "$bundle") the files meet:"
    echo "$met" | sed 's/^/  /'
    bad=1
  fi
done <"$list"
[ "$bundles" -gt 0 ] || { echo "FAIL: no bundle in $list"; exit 1; }
[ "$bad" = 0 ] || exit 1
echo "no two files of $bundles bundles meet ($("$ctags" --version | head -1 | cut -d, -f1))"
