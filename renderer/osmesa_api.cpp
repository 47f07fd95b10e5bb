#include "osmesa_api.h"

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <exception>
#include <string>

namespace renderer::osmesa {

namespace {

/// libOSMesa's functions, looked up at the first context. Linked in, the library and everything it
/// needs (LLVM for llvmpipe, and LLVM's own dependencies) were loaded and relocated at the start of
/// every command, drawing or not: `shadowscope --version` took 21 ms and 60 MiB, a third of a 1 M
/// triangle `mesh info`'s start-up.
struct Api {
    decltype(&OSMesaCreateContextAttribs) createContextAttribs = nullptr;
    decltype(&OSMesaMakeCurrent) makeCurrent = nullptr;
    decltype(&OSMesaDestroyContext) destroyContext = nullptr;
    decltype(&OSMesaGetProcAddress) getProcAddress = nullptr;
    std::string error; // why the functions are missing
};

constexpr const char* kLibrary = "libOSMesa.so.8"; // Mesa's soname (Debian's libosmesa6)

template <class F> void lookUp(void* library, const char* name, F& f) noexcept {
    f = reinterpret_cast<F>(dlsym(library, name));
}

const Api& api() {
    static const Api loaded = [] {
        Api a;
        // Never closed: a context may live until the process ends.
        void* library = dlopen(kLibrary, RTLD_NOW | RTLD_LOCAL);
        if (!library) {
            const char* why = dlerror();
            a.error = std::string("OSMesa could not be loaded: ") + (why ? why : kLibrary);
            return a;
        }
        lookUp(library, "OSMesaCreateContextAttribs", a.createContextAttribs);
        lookUp(library, "OSMesaMakeCurrent", a.makeCurrent);
        lookUp(library, "OSMesaDestroyContext", a.destroyContext);
        lookUp(library, "OSMesaGetProcAddress", a.getProcAddress);
        if (!a.createContextAttribs || !a.makeCurrent || !a.destroyContext || !a.getProcAddress)
            a.error = std::string(kLibrary) + " lacks the OSMesa functions this program calls";
        return a;
    }();
    return loaded;
}

} // namespace

void* create(std::string& error) noexcept {
    try {
        const Api& gl = api();
        if (!gl.error.empty()) {
            error = gl.error;
            return nullptr;
        }
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
        OSMesaContext ctx = gl.createContextAttribs(attribs, nullptr);
        if (!ctx) error = "OSMesa could not create a GL 4.5 core context";
        return ctx;
    } catch (const std::exception&) { // the error text's allocation
        error = "OSMesa could not be loaded";
        return nullptr;
    }
}

// The three below are only called with a context create() made, so the functions are there.
bool makeCurrent(void* context, unsigned char* buffer) noexcept {
    return api().makeCurrent(static_cast<OSMesaContext>(context), buffer, GL_UNSIGNED_BYTE, kBufferSide, kBufferSide) ==
           GL_TRUE;
}

void destroy(void* context) noexcept {
    if (context) api().destroyContext(static_cast<OSMesaContext>(context));
}

void* procAddress(const char* name) noexcept { return reinterpret_cast<void*>(api().getProcAddress(name)); }

} // namespace renderer::osmesa
