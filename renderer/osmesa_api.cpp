#include "osmesa_api.h"

#include <GL/osmesa.h>

namespace renderer::osmesa {

void* create(std::string& error) noexcept {
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           24,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           4,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           5,
                           0};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!ctx) error = "OSMesa could not create a GL 4.5 core context";
    return ctx;
}

bool makeCurrent(void* context, unsigned char* buffer) noexcept {
    return OSMesaMakeCurrent(static_cast<OSMesaContext>(context), buffer, GL_UNSIGNED_BYTE, kBufferSide, kBufferSide) ==
           GL_TRUE;
}

void destroy(void* context) noexcept { OSMesaDestroyContext(static_cast<OSMesaContext>(context)); }

void* procAddress(const char* name) noexcept { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); }

} // namespace renderer::osmesa
