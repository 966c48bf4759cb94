#!/usr/bin/env bash
# Installs every package the project needs, on Debian 12 or 13 or Ubuntu 22.04 or 24.04 (it names
# the platform it found, and stops with a clear message on any other). Idempotent: installs only
# what is missing, and does nothing (not even `apt-get update`) when everything is there.
# Installing needs root (sudo, or su where there is no sudo); with everything installed, any user
# may run it (it says so and does nothing).
set -euo pipefail

# The platform.
os_id="" os_version="" os_name="a system without /etc/os-release"
if [ -r /etc/os-release ]; then
  os_id=$(. /etc/os-release && echo "${ID:-}")
  os_version=$(. /etc/os-release && echo "${VERSION_ID:-}")
  os_name=$(. /etc/os-release && echo "${PRETTY_NAME:-$ID $VERSION_ID}")
fi
case "$os_id:$os_version" in
  debian:12 | debian:13 | ubuntu:22.04 | ubuntu:24.04) ;;
  *)
    echo "install-deps: this is $os_name; the project supports Debian 12 and 13 and Ubuntu 22.04" \
      "and 24.04 (README.md, \"Platforms\"): on macOS or Windows, use the dev container or WSL 2" >&2
    exit 1
    ;;
esac
echo "install-deps: $os_name"

packages=(
  # toolchain
  g++ cmake ninja-build pkg-config git
  patch              # the wrong versions and alternatives are patches of the solution (cmake/A6Variants.cmake)
  ccache mold        # faster rebuilds (cmake/A6FastBuild.cmake): used when present, never required
  # libraries (found with find_package / pkg-config)
  libeigen3-dev      # Eigen 3.4
  libbox2d-dev       # Box2D 2.4.1
  libgtest-dev       # GoogleTest 1.12
  libbenchmark-dev   # Google Benchmark
  nlohmann-json3-dev # JSON (manifests, reports, the probe's pipe)
  libtomlplusplus-dev  # TOML (the grader's rubric)
  libcli11-dev       # command lines of the grader's tools
  libarchive-dev     # reading submitted zips and tarballs
  libyaml-cpp-dev    # YAML (a Gradescope export's submission_metadata.yml, a6_batch)
  libseccomp-dev     # the probe's system-call filter
  libstb-dev         # stb_image_write / stb_image (PNG)
  libosmesa6-dev     # OSMesa: headless OpenGL (Mesa 22.3, llvmpipe)
  libegl-dev         # EGL (surfaceless headless backend)
  libglfw3-dev       # GLFW 3.3: the viewer's window
  libimgui-dev       # Dear ImGui: the viewer's widgets
  xvfb xauth         # a virtual X server for the viewer's smoke test
  x11vnc novnc websockify  # the desktop in the browser (scripts/desktop.sh): the viewer anywhere
  fonts-dejavu-core  # the viewer panel's font (Greek letters, ×)
  zip unzip          # the Gradescope autograder zip (scripts/gradescope-package.sh) and its test
  jq                 # JSON on the command line (scripts/instructor.sh reads results.json)
  similarity-tester  # sim_c++: code similarity between submissions (a6_batch --similarity)
  universal-ctags    # each function's first and last line (tests/format/function_size_test.sh)
)

# Per platform: Debian gets Chromium, the headless browser that checks the desktop in the
# browser (ctest viewer_desktop_in_browser; Ubuntu's chromium is a snap, which chroots and
# containers cannot run, so the test skips there); Debian 12 also gets g++-11, Ubuntu 22.04's
# compiler, for the Gradescope image's check (scripts/compat-ubuntu2204.sh), and clang-format 14,
# for the layout test (tests/format/); Ubuntu 22.04 has no toml++ package (the Gradescope zip
# carries a copy of it; a checkout there builds everything but the grader, cmake/A6Toml.cmake).
case "$os_id:$os_version" in
  debian:12) packages+=(chromium g++-11 clang-format) ;;
  debian:13) packages+=(chromium) ;;
  ubuntu:22.04)
    echo "install-deps: Ubuntu 22.04 has no libtomlplusplus-dev: skipped" >&2
    for i in "${!packages[@]}"; do [ "${packages[$i]}" = libtomlplusplus-dev ] && unset 'packages[i]'; done
    ;;
esac

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: missing packages: ${missing[*]}" >&2
  # Named as this machine can run it: with sudo where it is installed, else as root with su.
  self="$(cd "$(dirname "$0")" && pwd)/$(basename "$0")"
  if command -v sudo >/dev/null 2>&1; then
    echo "install-deps: installing needs root: run  sudo bash $self" >&2
  else
    echo "install-deps: installing needs root (this system has no sudo): run  su - -c 'bash $self'" \
      "and give root's password (su -: root's own PATH, which apt needs); then go on as yourself" >&2
  fi
  exit 1
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -q
apt-get install -y -q --no-install-recommends "${missing[@]}"
