# Sourced by the format tests that measure with Universal Ctags (function_size_test.sh,
# bundles_test.sh): sets ctags to its command (Debian's package names it ctags-universal, and
# ctags unless another ctags holds that name), or exits 77, ctest's skip, when there is none.
ctags=""
for c in ctags-universal ctags; do
  if command -v "$c" >/dev/null && "$c" --version 2>/dev/null | grep -q '^Universal Ctags'; then
    ctags="$c"; break
  fi
done
[ -n "$ctags" ] || { echo "SKIP: no Universal Ctags (Debian's universal-ctags package)"; exit 77; }
