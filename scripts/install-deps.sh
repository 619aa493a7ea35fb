#!/usr/bin/env bash
# Installs every build, test and benchmark dependency of Physics Sandbox from Debian 12 packages.
# Skips packages that are already installed; needs root (or sudo) only when something is missing.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libosmesa6-dev      # off-screen Mesa context (llvmpipe)
  libegl-dev          # EGL headless back end (surfaceless or device platform) ...
  libegl-mesa0        # ... Mesa's EGL driver ...
  libgl1-mesa-dri     # ... and its llvmpipe (swrast) DRI driver
  libopengl-dev       # glvnd's libOpenGL: GL entry points for a build with EGL and no OSMesa
  python3-glad        # GLAD 2 generator (the `glad` command), run offline at configure time
  libimgui-dev        # Dear ImGui 1.86 with the OpenGL2 back end
  libstb-dev          # imgui's pkg-config wants -lstb
  libtinyobjloader-dev
  libgtest-dev
  libbenchmark-dev
  libpng-dev          # PNG encoder for frames
  nlohmann-json3-dev  # scene files (--scene): JSON parsing, header-only
  gnuplot-nox         # speed/accuracy plots (bench/)
  ccache              # faster rebuilds (optional at build time)
  libglfw3-dev        # --window: the desktop window (X11)
  xvfb xdotool        # the window test: a private X display, driven by synthetic mouse input
  ffmpeg              # --video: MP4, WebM and GIF recording (the ffmpeg and ffprobe programs)
  chromium            # the review.browser CTest opens scripts/review-goldens.sh's page in headless Chromium
  parallel            # GNU parallel: scripts/sweep-parallel.sh runs sweep shards on cores or ssh hosts
  clang               # libFuzzer targets (scripts/fuzz.sh, docs/testing.md)
  libclang-rt-14-dev  # clang 14's libFuzzer and sanitizer runtimes (only Recommended by clang, so named here)
  libbullet-dev       # Bullet 3.24, the peer engine of psb-peer-bench (bench/peers; optional at build time)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
as_root=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  as_root=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
