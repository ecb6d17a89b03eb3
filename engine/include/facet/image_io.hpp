#pragma once
// Image files written and read through stb.

#include <cstdint>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/framebuffer.hpp"

namespace facet {

/// Writes the colour plane as an 8-bit RGB PNG.
Status writePng(const Framebuffer& frame, const std::string& path);

/// The bytes writePng() writes for `frame` (8-bit RGB PNG), for a stream or a pipe.
Result<std::string> encodePng(const Framebuffer& frame);

/// Writes packed RGBA pixels (row 0 at the top) as an 8-bit RGB PNG.
Status writePng(const std::uint32_t* rgba, int width, int height, const std::string& path);

}  // namespace facet
