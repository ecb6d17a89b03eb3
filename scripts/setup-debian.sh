#!/usr/bin/env bash
# Installs the Debian 12 packages facet needs to build, test and run (apt-get, as root or through
# sudo); does nothing when they are all present.
set -euo pipefail
pkgs=(build-essential cmake pkg-config
  libglfw3-dev libglm-dev libimgui-dev libstb-dev libtinyobjloader-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev libepoxy-dev libegl-dev libgl1-mesa-dri
  ninja-build
  libpng-dev libjpeg62-turbo-dev  # PNG and JPEG textures (libpng, libjpeg-turbo)
  clang libclang-rt-14-dev libomp-dev  # make test-clang and make fuzz (libFuzzer, sanitizers, OpenMP)
  libhwy-dev  # Google Highway: the span loop's SIMD, SSE4/AVX2/AVX-512 chosen at run time
  libegl1 libegl-mesa0 libgbm1  # the OpenGL twin: EGL's surfaceless platform on Mesa (llvmpipe)
  xvfb xauth xdotool x11-utils  # the viewer's tests: a virtual display, real input events, xprop
  gnuplot-nox)  # facet bench --chart
# Extra packages named on the command line (e.g. doxygen for make doc).
pkgs+=("$@")
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then exit 0; fi
echo "facet: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
