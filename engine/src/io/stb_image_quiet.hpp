#pragma once
// stb_image with its own warnings silenced (it is third-party C, written for other flags). The
// includer picks the decoders first: STBI_ONLY_*, STBI_NO_STDIO, STB_IMAGE_STATIC and
// STB_IMAGE_IMPLEMENTATION.

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wnull-dereference"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
