#!/usr/bin/env bash
# Proof, without an Ubuntu machine, that the Gradescope zip builds and grades on Ubuntu 22.04
# (Gradescope's default image): the zip's own setup.sh and run_autograder, run with the
# toolchain versions 22.04 ships (CMake 3.22.1, g++ 11, GoogleTest 1.11.0, nlohmann-json 3.10.5)
# in a private mount namespace where /etc/os-release says Ubuntu 22.04 and this machine's toml++,
# GoogleTest and nlohmann-json are hidden. The solution must get 113 (100 + 13 extra credit), the
# starter 0.
#
#   scripts/compat-ubuntu2204.sh            (as root: the mount namespace needs it)
#
# The toolchain is built once from ../shared/compat (or $A6_COMPAT_SOURCES) into
# /var/cache/a6-compat (or $A6_COMPAT_CACHE), outside the checkout, and reused. g++-11 is
# Debian 12's package (scripts/install-deps.sh installs it there).
# Exit status: 0 when it holds; 1 when it does not; 77 when it cannot be tried here (no root, no
# sources, no g++-11: the reason is printed).
set -uo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
sources="${A6_COMPAT_SOURCES:-$repo/../shared/compat}"
cache="${A6_COMPAT_CACHE:-/var/cache/a6-compat}"
start=$(date +%s)
say() { printf 'compat: %s\n' "$*"; }
skip() { say "skipped: $*"; exit 77; }
die() { say "FAILED: $*"; exit 1; }

[ "$(id -u)" -eq 0 ] || skip "not root (a private mount namespace needs it)"
[ -f "$sources/SHA256SUMS" ] || skip "no toolchain sources in $sources (../shared/compat)"
command -v g++-11 >/dev/null || skip "no g++-11 (Debian 12: apt-get install g++-11)"
command -v unshare >/dev/null || skip "no unshare (util-linux)"

# ---- 1. the 22.04 toolchain, built once ------------------------------------------------------
toolchain() {
  local stamp="$cache/built-from" want
  want="$(cat "$sources/SHA256SUMS")"
  [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ] && return 0
  say "building the Ubuntu 22.04 toolchain into $cache (once)"
  rm -rf "$cache" && mkdir -p "$cache/src/gtest" "$cache/src/json" || return 1
  (cd "$sources" && sha256sum --quiet -c SHA256SUMS) || { say "checksums differ in $sources"; return 1; }
  tar xzf "$sources/cmake-3.22.1-debian12-amd64.tar.gz" -C "$cache" &&
    tar xzf "$sources/googletest-1.11.0.tar.gz" -C "$cache/src/gtest" &&
    tar xzf "$sources/nlohmann-json-3.10.5.tar.gz" -C "$cache/src/json" || return 1
  local cmake="$cache/cmake-3.22.1/bin/cmake"
  "$cmake" -S "$cache/src/gtest" -B "$cache/b/gtest" -G Ninja -DCMAKE_CXX_COMPILER=g++-11 \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$cache/prefix" >"$cache/gtest.log" 2>&1 &&
    "$cmake" --build "$cache/b/gtest" >>"$cache/gtest.log" 2>&1 &&
    "$cmake" --install "$cache/b/gtest" >>"$cache/gtest.log" 2>&1 || { tail "$cache/gtest.log"; return 1; }
  "$cmake" -S "$cache/src/json" -B "$cache/b/json" -G Ninja -DJSON_BuildTests=OFF \
    -DCMAKE_INSTALL_PREFIX="$cache/prefix" >"$cache/json.log" 2>&1 &&
    "$cmake" --install "$cache/b/json" >>"$cache/json.log" 2>&1 || { tail "$cache/json.log"; return 1; }
  rm -rf "$cache/src" "$cache/b"
  echo "$want" >"$stamp"
}
t=$(date +%s)
toolchain || die "the toolchain could not be built (above)"
version_of() {  # version_of PACKAGE: from its CMake config in the prefix
  find "$cache/prefix" -name "${1}ConfigVersion.cmake" -exec grep -oh 'PACKAGE_VERSION "[0-9.]*"' {} + |
    head -n 1 | tr -dc '0-9.'
}
say "toolchain: $("$cache/cmake-3.22.1/bin/cmake" --version | head -n 1), $(g++-11 --version | head -n 1)," \
  "GoogleTest $(version_of GTest), nlohmann-json $(version_of nlohmann_json) ($(($(date +%s) - t)) s)"

# ---- 2. the zip, unpacked into a fake /autograder ----------------------------------------------
work="$(mktemp -d /tmp/a6-compat.XXXXXX)"
trap 'rm -rf "$work"' EXIT
chmod 755 "$work"
bash "$repo/scripts/gradescope-package.sh" "$work/a6_autograder.zip" >"$work/package.log" 2>&1 ||
  { tail "$work/package.log"; die "the zip could not be made"; }
mkdir -p "$work/autograder/source" "$work/autograder/submission" "$work/autograder/results"
(cd "$work/autograder/source" && unzip -q "$work/a6_autograder.zip") || die "cannot unzip the zip"
cp "$work/autograder/source/run_autograder" "$work/autograder/run_autograder"
[ -d "$work/autograder/source/vendor/tomlplusplus/include/toml++" ] || die "the zip carries no toml++"

# ---- 3. Ubuntu 22.04, as far as the build can tell ---------------------------------------------
cat >"$work/os-release" <<'EOF'
PRETTY_NAME="Ubuntu 22.04.5 LTS"
NAME="Ubuntu"
VERSION_ID="22.04"
VERSION="22.04.5 LTS (Jammy Jellyfish)"
VERSION_CODENAME=jammy
ID=ubuntu
ID_LIKE=debian
UBUNTU_CODENAME=jammy
EOF
arch_lib=/usr/lib/x86_64-linux-gnu
hidden_dirs=(/usr/include/toml++ "$arch_lib/cmake/tomlplusplus" /usr/include/gtest /usr/include/gmock
  "$arch_lib/cmake/GTest" /usr/include/nlohmann /usr/share/cmake/nlohmann_json)
hidden_files=("$arch_lib/pkgconfig/tomlplusplus.pc" "$arch_lib/libtomlplusplus.so"
  "$arch_lib/libgtest.a" "$arch_lib/libgtest_main.a" "$arch_lib/libgmock.a" "$arch_lib/libgmock_main.a"
  "$arch_lib/pkgconfig/gtest.pc" "$arch_lib/pkgconfig/gtest_main.pc" "$arch_lib/pkgconfig/gmock.pc"
  "$arch_lib/pkgconfig/gmock_main.pc" "$arch_lib/pkgconfig/nlohmann_json.pc" /usr/share/pkgconfig/nlohmann_json.pc)

# What runs inside the namespace: the hiding, then setup.sh and run_autograder as Gradescope
# runs them.
cat >"$work/inside.sh" <<'EOF'
set -uo pipefail
for d in $HIDDEN_DIRS; do [ -d "$d" ] && mount -t tmpfs -o ro,size=4k none "$d"; done
for f in $HIDDEN_FILES; do [ -e "$f" ] && mount --bind /dev/null "$f"; done
mount --bind "$WORK/os-release" /etc/os-release
[ -e /usr/lib/os-release ] && mount --bind "$WORK/os-release" /usr/lib/os-release
export PATH="$CACHE/cmake-3.22.1/bin:$PATH" CXX=g++-11 CMAKE_PREFIX_PATH="$CACHE/prefix"
export A6_AUTOGRADER_ROOT="$WORK/autograder"
echo "inside: $(. /etc/os-release && echo "$PRETTY_NAME"); cmake $(cmake --version | head -n 1 | cut -d' ' -f3);" \
  "toml++ headers visible: $([ -e /usr/include/toml++/toml.h ] && echo yes || echo no);" \
  "GoogleTest headers visible: $([ -e /usr/include/gtest/gtest.h ] && echo yes || echo no)"
A6_SKIP_APT=1 bash "$WORK/autograder/source/setup.sh" >"$WORK/setup.log" 2>&1
echo "setup.sh exit status $?"
for who in solution starter; do
  rm -rf "$WORK/autograder/submission" "$WORK/autograder/results"
  mkdir -p "$WORK/autograder/submission" "$WORK/autograder/results"
  cp "$REPO/$who"/*.cpp "$WORK/autograder/submission/"
  (cd "$WORK/autograder" && ./run_autograder >"$WORK/$who.log" 2>&1)
  cp "$WORK/autograder/results/results.json" "$WORK/$who.json" 2>/dev/null
done
EOF
t=$(date +%s)
WORK="$work" CACHE="$cache" REPO="$repo" HIDDEN_DIRS="${hidden_dirs[*]}" HIDDEN_FILES="${hidden_files[*]}" \
  unshare --mount --propagation private bash "$work/inside.sh" || die "the namespace could not be set up"
setup_seconds=$(($(date +%s) - t))

# ---- 4. what must hold -------------------------------------------------------------------------
failures=0
check() {  # check WHAT CONDITION...
  local what="$1"
  shift
  if "$@"; then say "ok: $what"; else say "FAILED: $what"; failures=$((failures + 1)); fi
}
cache_value() { sed -n "s/^$1:[A-Z]*=//p" "$work/autograder/source/build/CMakeCache.txt"; }
grep -q '^setup.sh: base image: Ubuntu 22.04' "$work/setup.log" || tail -20 "$work/setup.log"
check "setup.sh saw Ubuntu 22.04 and finished" grep -q '^setup.sh: base image: Ubuntu 22.04' "$work/setup.log"
check "setup.sh succeeded" bash -c "! grep -q 'ERROR' '$work/setup.log'"
check "CMake 3.22.1 configured the grader" test "$(cache_value CMAKE_COMMAND)" = "$cache/cmake-3.22.1/bin/cmake"
check "g++ 11 compiled it" bash -c "grep -q 'CMAKE_CXX_COMPILER:.*g++-11' '$work/autograder/source/build/CMakeCache.txt'"
check "GoogleTest 1.11 from the 22.04 toolchain" test "$(cache_value GTest_DIR)" = "$cache/prefix/lib/cmake/GTest"
check "toml++ from the zip's copy" bash -c "grep -q 'A6_TOMLPLUSPLUS_INCLUDE:PATH=$work/autograder/source/vendor' '$work/autograder/source/build/CMakeCache.txt'"
score() { jq -r '.score' "$work/$1.json" 2>/dev/null; }
say "solution: $(score solution), starter: $(score starter)"
check "the solution gets 113 (100 + 13 extra credit)" test "$(score solution)" = 113
check "the starter gets 0" bash -c "[ '$(score starter)' = 0 ] || [ '$(score starter)' = 0.0 ]"
say "setup.sh and two gradings in $setup_seconds s; $(($(date +%s) - start)) s in all"
if [ "$failures" -gt 0 ]; then
  say "setup.sh's output (last lines):"
  tail -15 "$work/setup.log"
  exit 1
fi
say "the Gradescope zip builds and grades under Ubuntu 22.04's toolchain"
