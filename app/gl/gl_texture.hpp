#pragma once
// The scene's texture on the GL side. The engine's own mip chain is uploaded level by level
// (not glGenerateMipmap), so both renderers filter the very same texels; only the levels a
// filter reads are sent, and a texture is sent once while the scene keeps it.

#include <cstddef>
#include <memory>

#include "facet/settings.hpp"
#include "facet/texture.hpp"
#include "gl_objects.hpp"

namespace facet::gl {

/// One GL texture mirroring the last facet::Texture bound.
class TextureCache {
  public:
    /// Binds `texture` (a 1×1 white one when null, as the engine samples) to unit 0 with
    /// `filter` and repeat wrap, uploading what is missing: level 0 for nearest and bilinear,
    /// the whole chain for trilinear. Returns the bytes uploaded.
    std::size_t bind(const std::shared_ptr<const Texture>& texture, TextureFilter filter);

  private:
    // Holding the source keeps its address from being reused by another texture while cached.
    std::shared_ptr<const Texture> source_;
    std::shared_ptr<const Texture> white_;
    TextureName name_;
    int levels_ = 0;  ///< levels uploaded, from 0
};

}  // namespace facet::gl
