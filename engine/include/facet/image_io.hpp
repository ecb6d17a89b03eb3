#pragma once
// PNG files written through libpng, at its fastest settings (8-bit RGB; zlib level 1, Sub filter).

#include <cstdint>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/load_control.hpp"

namespace facet {

/// Writes the colour plane as an 8-bit RGB PNG; `control` (optional) hears the rows written.
Status writePng(const Framebuffer& frame, const std::string& path,
                const LoadControl* control = nullptr);

/// The bytes writePng() writes for `frame` (8-bit RGB PNG), for a stream or a pipe.
Result<std::string> encodePng(const Framebuffer& frame, const LoadControl* control = nullptr);

/// Writes packed RGBA pixels (row 0 at the top) as an 8-bit RGB PNG.
Status writePng(const std::uint32_t* rgba, int width, int height, const std::string& path,
                const LoadControl* control = nullptr);

}  // namespace facet
