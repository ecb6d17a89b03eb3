#!/usr/bin/env bash
# The library as a user gets it (docs/library.md): installs facet into a temporary prefix, builds
# examples/ there as an outside CMake project with find_package(facet), runs each example, and
# links a one-file program with `pkg-config --cflags --libs facet`. Exits non-zero on the first
# failure; everything it makes is in a temporary folder, removed afterwards.
#
#   scripts/check-install.sh BUILD   installs from an existing build folder (CI: the one `make
#                                    test` built, so nothing is compiled twice)
#   scripts/check-install.sh         first configures and builds the libraries alone (no app,
#                                    viewer or tests: what an add_subdirectory user pulls in)
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)

if [[ $# -ge 1 ]]; then
  build="$1"
else
  build="$work/build"
  echo "== configure and build the libraries alone"
  cmake -S "$src" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release \
    -DFACET_BUILD_APP=OFF -DFACET_BUILD_VIEWER=OFF -DFACET_BUILD_TESTS=OFF \
    -DFACET_BUILD_EXAMPLES=OFF -DFACET_INSTALL=ON >/dev/null
  cmake --build "$build"
fi
echo "== install into a temporary prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
test -f "$prefix/include/facet/version.hpp"
test -n "$(find "$prefix" -name facetConfig.cmake)"

echo "== examples/ as an outside project: find_package(facet)"
cmake -S "$src/examples" -B "$work/examples" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$work/examples"

echo "== run each example"
"$work/examples/render_scene" "$src/assets/default.scene" "$work/scene.png"
"$work/examples/mesh_in_code" "$work/pyramid.png"
"$work/examples/compare_settings" "$src/assets/default.scene"
for png in scene.png pyramid.png; do
  head -c 8 "$work/$png" | od -An -c | grep -q 'P   N   G' || {
    echo "$png is not a PNG" >&2
    exit 1
  }
done
# An error is a value and a message, not a crash: a file that does not exist.
if "$work/examples/render_scene" "$work/no_such.scene" "$work/x.png" 2>"$work/err.txt"; then
  echo "render_scene accepted a missing file" >&2
  exit 1
fi
grep -q "no_such.scene" "$work/err.txt"

echo "== pkg-config --cflags --libs facet: a one-file program"
cat >"$work/one_file.cpp" <<'CPP'
#include <cstdio>

#include "facet/render.hpp"
#include "facet/version.hpp"

int main() {
    facet::Scene scene;  // an empty mesh: a frame of background
    scene.camera.width = -10;
    facet::Renderer renderer;
    facet::Framebuffer frame;
    const facet::Result<facet::RenderStats> refused = renderer.render(scene, {}, frame);
    scene.camera.width = 64;
    const facet::Result<facet::RenderStats> drawn = renderer.render(scene, {}, frame);
    std::printf("facet %s: %s; %dx%d\n", facet::kVersionString,
                refused ? "accepted" : refused.error().what().c_str(), frame.width, frame.height);
    return !refused && drawn ? 0 : 1;
}
CPP
export PKG_CONFIG_PATH="$(dirname "$(find "$prefix" -name facet.pc | head -n 1)")${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
# shellcheck disable=SC2046 # pkg-config's output is meant to split into words
"${CXX:-c++}" -std=c++20 -O1 "$work/one_file.cpp" -o "$work/one_file" $(pkg-config --cflags --libs facet)
"$work/one_file"
echo "== the installed library works: $(pkg-config --modversion facet)"
