#pragma once
// What every fuzz target asserts about a loader's success: a crash (trap) here is a finding just
// like a sanitizer report, since a mesh that breaks these would make the renderer read out of
// bounds.

#include <cmath>
#include <cstdlib>

#include "facet/mesh.hpp"

namespace facet::fuzz {

/// Stops the run (a libFuzzer finding) when `ok` is false.
inline void require(bool ok) {
    if (!ok) std::abort();
}

/// The invariants the renderer relies on: whole triangles, indices in range, one colour and uv
/// per vertex (or none), finite positions.
inline void checkMesh(const Mesh& mesh) {
    const std::size_t n = mesh.positions.size();
    require(mesh.indices.size() % 3 == 0);
    for (const std::uint32_t i : mesh.indices) require(i < n);
    require(mesh.colors.empty() || mesh.colors.size() == n);
    require(mesh.uvs.empty() || mesh.uvs.size() == n);
    for (const auto& p : mesh.positions) {
        require(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    }
}

}  // namespace facet::fuzz
