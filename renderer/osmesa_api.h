#pragma once
// The few OSMesa calls, behind an opaque handle: <GL/osmesa.h> pulls in <GL/gl.h>, which must
// not meet the loader's <GL/glcorearb.h>, so only osmesa_api.cpp includes it.
#include <string>

namespace renderer::osmesa {

inline constexpr int kBufferSide = 16; // drawing goes to framebuffer objects; this buffer is unused

/// A GL 4.5 core context, or nullptr with `error` set.
void* create(std::string& error) noexcept;
bool makeCurrent(void* context, unsigned char* buffer) noexcept;
void destroy(void* context) noexcept;
void* procAddress(const char* name) noexcept;

} // namespace renderer::osmesa
