#!/usr/bin/env bash
# Installs every Debian 12 package the project needs. Idempotent: installs only what is
# missing, and does nothing (not even `apt-get update`) when everything is there.
# Run as root (or with sudo).
set -euo pipefail

packages=(
  # toolchain
  g++ cmake ninja-build pkg-config git
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
  libseccomp-dev     # the probe's system-call filter
  libstb-dev         # stb_image_write / stb_image (PNG)
  libosmesa6-dev     # OSMesa: headless OpenGL (Mesa 22.3, llvmpipe)
  libegl-dev         # EGL (surfaceless headless backend)
  libglfw3-dev       # GLFW 3.3: the viewer's window
  libimgui-dev       # Dear ImGui: the viewer's widgets
  xvfb xauth         # a virtual X server for the viewer's smoke test
  fonts-dejavu-core  # the viewer panel's font (Greek letters, ×)
  zip unzip          # the Gradescope autograder zip (scripts/gradescope-package.sh) and its test
  jq                 # JSON on the command line (scripts/instructor.sh reads results.json)
)

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
  echo "install-deps: run this script as root (or with sudo) to install them" >&2
  exit 1
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -q
apt-get install -y -q --no-install-recommends "${missing[@]}"
