#!/usr/bin/env bash
# The library as a user gets it (docs/library.md): installs facet into a temporary prefix, builds
# examples/ there as an outside CMake project with find_package(facet), runs each example, and
# links a one-file program with `pkg-config --cflags --libs facet` (the engine alone) and one with
# `facet-evaluation`; checks that the engine's archive needs nothing of the evaluation library's
# and that examples/ uses no advanced (unstable) header; then consumes the source tree as a
# subproject (FetchContent from the folder, a program on facet::engine and one on
# facet::evaluation built and run; FetchContent from a file:// git URL of the clone and
# add_subdirectory, configured), checking that only the libraries are built: no GoogleTest,
# GLFW, ImGui, epoxy or CLI11 looked for, and the parent's build type left alone.
# Exits non-zero on the first failure; everything it makes is in a temporary folder, removed
# afterwards.
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
test -f "$prefix/include/facet/evaluation/image_diff.hpp"
test -f "$prefix/include/facet/advanced/draw.hpp"
test -n "$(find "$prefix" -name facetConfig.cmake)"
# The engine does not depend on the evaluation library: nothing the engine's archive needs is
# defined there (strong definitions only; inline functions both use are weak in each).
libdir="$(dirname "$(find "$prefix" -name libfacet_engine.a | head -n 1)")"
nm --undefined-only "$libdir/libfacet_engine.a" | awk 'NF == 2 {print $2}' | sort -u >"$work/engine-needs.txt"
nm --defined-only --extern-only "$libdir/libfacet_evaluation.a" |
  awk 'NF == 3 && $2 ~ /^[TDBR]$/ {print $3}' | sort -u >"$work/evaluation-has.txt"
if [[ -n "$(comm -12 "$work/engine-needs.txt" "$work/evaluation-has.txt")" ]]; then
  echo "the engine library needs symbols of the evaluation library:" >&2
  comm -12 "$work/engine-needs.txt" "$work/evaluation-has.txt" | c++filt >&2
  exit 1
fi
# The examples are what users copy: the stable API only, no advanced (unstable) header.
if grep -rn 'facet/advanced/' "$src/examples"; then
  echo "examples/ uses the advanced API (facet/advanced/), which is not stable" >&2
  exit 1
fi

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
# The evaluation library through its own facet-evaluation.pc (which requires facet.pc).
cat >"$work/one_file_evaluation.cpp" <<'CPP'
#include <cstdio>

#include "facet/evaluation/image_diff.hpp"
#include "facet/render.hpp"

int main() {
    facet::Scene scene;  // an empty mesh: frames of background
    scene.camera.width = 32;
    scene.camera.height = 24;
    facet::Renderer renderer;
    facet::Framebuffer a, b;
    facet::RenderSettings black;
    black.background = 0x000000;
    facet::RenderSettings white;
    white.background = 0xffffff;
    if (!renderer.render(scene, black, a) || !renderer.render(scene, white, b)) return 1;
    const facet::ImageDiff same = facet::diffImages(a, a);
    const facet::ImageDiff apart = facet::diffImages(a, b);
    std::printf("evaluation: %zu and %zu of %zu pixels differ\n", same.pixelsDiffering,
                apart.pixelsDiffering, apart.pixels);
    return same.pixelsDiffering == 0 && apart.pixelsDiffering == 32u * 24u &&
                   apart.maxError == 255
               ? 0
               : 1;
}
CPP
# shellcheck disable=SC2046 # pkg-config's output is meant to split into words
"${CXX:-c++}" -std=c++20 -O1 "$work/one_file_evaluation.cpp" -o "$work/one_file_evaluation" \
  $(pkg-config --cflags --libs facet-evaluation)
"$work/one_file_evaluation"
echo "== the installed libraries work: $(pkg-config --modversion facet facet-evaluation | paste -sd' ')"

echo "== facet as a subproject: FetchContent and add_subdirectory, the engine alone"
mkdir -p "$work/consumer"
cat >"$work/consumer/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.22)
project(facet_consumer LANGUAGES CXX)
set(FACET_SOURCE "" CACHE STRING "facet's source: a folder or a git URL")
set(FACET_TAG "" CACHE STRING "the commit to check out when FACET_SOURCE is a git URL")
option(FACET_AS_SUBDIRECTORY "add_subdirectory instead of FetchContent" OFF)
if(FACET_AS_SUBDIRECTORY)
  add_subdirectory(${FACET_SOURCE} facet)
else()
  include(FetchContent)
  if(FACET_TAG)
    FetchContent_Declare(facet GIT_REPOSITORY ${FACET_SOURCE} GIT_TAG ${FACET_TAG})
  else()
    FetchContent_Declare(facet SOURCE_DIR ${FACET_SOURCE})
  endif()
  FetchContent_MakeAvailable(facet)
endif()
add_executable(consumer main.cpp)
target_link_libraries(consumer PRIVATE facet::engine)
add_executable(consumer_evaluation evaluation.cpp)
target_link_libraries(consumer_evaluation PRIVATE facet::evaluation)
CMAKE
cp "$work/one_file_evaluation.cpp" "$work/consumer/evaluation.cpp"
cat >"$work/consumer/main.cpp" <<'CPP'
#include <cstdio>

#include "facet/image_io.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"

int main(int argc, char** argv) {
    if (argc != 3) return 2;
    facet::Result<facet::Scene> scene = facet::openSceneFile(argv[1]);
    if (!scene) {
        std::fprintf(stderr, "%s\n", scene.error().what().c_str());
        return 1;
    }
    facet::Renderer renderer;
    facet::Framebuffer frame;
    if (!renderer.render(scene.value(), {}, frame) || !facet::writePng(frame, argv[2])) return 1;
    std::printf("consumer: %dx%d\n", frame.width, frame.height);
    return 0;
}
CPP
# Only the engine's targets and none of the app's dependencies; the parent's build type kept.
only_the_engine() {
  local dir="$1" type="$2"
  grep -qx "CMAKE_BUILD_TYPE:STRING=$type" "$dir/CMakeCache.txt" || {
    echo "$dir: the build type is not the parent's '$type'" >&2
    exit 1
  }
  if grep -Eq '^(GTest|GTEST|glfw3|CLI11|IMGUI|EPOXY|imgui)[A-Za-z_]*:' "$dir/CMakeCache.txt" ||
    cmake --build "$dir" --target help | grep -Eiq 'gtest|glfw|imgui|cli11|facet-view|^facet:'; then
    echo "$dir: facet as a subproject looked for or builds more than the engine" >&2
    exit 1
  fi
}
# FetchContent from the folder, no build type (the parent's choice, here none): built and run.
cmake -S "$work/consumer" -B "$work/fetch" "${generator[@]}" -DFACET_SOURCE="$src" >/dev/null
only_the_engine "$work/fetch" ""
cmake --build "$work/fetch"
"$work/fetch/consumer" "$src/assets/default.scene" "$work/consumer.png"
"$work/fetch/consumer_evaluation"
# add_subdirectory, Debug: configured (the same engine build as above).
cmake -S "$work/consumer" -B "$work/subdirectory" "${generator[@]}" -DCMAKE_BUILD_TYPE=Debug \
  -DFACET_SOURCE="$src" -DFACET_AS_SUBDIRECTORY=ON >/dev/null
only_the_engine "$work/subdirectory" Debug
# FetchContent from a file:// git URL of the clone at its current commit: configured.
if commit="$(git -C "$src" rev-parse HEAD 2>/dev/null)"; then
  cmake -S "$work/consumer" -B "$work/git" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DFACET_SOURCE="file://$src" -DFACET_TAG="$commit" >/dev/null
  only_the_engine "$work/git" RelWithDebInfo
  test -f "$work/git/_deps/facet-src/engine/include/facet/render.hpp"
fi
echo "== facet as a subproject: the engine alone, the parent's build type kept"
