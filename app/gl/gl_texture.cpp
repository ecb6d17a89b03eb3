#include "gl_texture.hpp"

namespace facet::gl {

std::size_t TextureCache::bind(const std::shared_ptr<const Texture>& texture,
                               TextureFilter filter) {
    if (!white_) white_ = std::make_shared<const Texture>();
    const std::shared_ptr<const Texture>& wanted = texture ? texture : white_;
    if (wanted != source_ || name_.get() == 0) {
        source_ = wanted;
        name_ = makeTexture();
        levels_ = 0;
    }
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, name_.get());

    const int needed = filter == TextureFilter::Trilinear ? source_->levelCount() : 1;
    std::size_t bytes = 0;
    if (levels_ < needed) {
        for (int i = levels_; i < needed; ++i) {
            const MipLevel& level = source_->level(i);
            // Row 0 (the image's top, v = 0) goes first: GL's t = 0 is the first row uploaded,
            // so uv need no flip. RGBA8 rows are never padded: the unpack alignment is moot.
            glTexImage2D(GL_TEXTURE_2D, i, GL_RGBA8, level.width, level.height, 0, GL_RGBA,
                         GL_UNSIGNED_BYTE, level.texels.data());
            bytes += level.texels.size() * sizeof(std::uint32_t);
        }
        levels_ = needed;
        // Only uploaded levels count, so the texture is complete whatever was sent.
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels_ - 1);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    }
    // spec §7: nearest is texel ⌊u'·W⌋ on level 0; bilinear blends the four nearest
    // texel centres of level 0; trilinear blends two levels' bilinear results. Below λ = 0
    // GL magnifies, which for trilinear is bilinear on level 0, like the engine's clamp.
    const GLint mag = filter == TextureFilter::Nearest ? GL_NEAREST : GL_LINEAR;
    const GLint min = filter == TextureFilter::Nearest    ? GL_NEAREST
                      : filter == TextureFilter::Bilinear ? GL_LINEAR
                                                          : GL_LINEAR_MIPMAP_LINEAR;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mag);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min);
    return bytes;
}

}  // namespace facet::gl
