// EGL headless context on the device platform: the first hardware device, else Mesa's software
// device, else the surfaceless platform. No display or window system needed.
#define EGL_NO_X11
#define MESA_EGL_NO_X11_HEADERS
#include "context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <stdexcept>
#include <vector>

namespace renderer {

namespace {

struct EglDevices {
    std::vector<EGLDeviceEXT> hardware, software;
};

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const size_t n = std::strlen(name);
    for (const char* p = std::strstr(list, name); p; p = std::strstr(p + n, name))
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

EglDevices enumerateDevices() {
    EglDevices out;
    const char* clientExt = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(clientExt, "EGL_EXT_device_enumeration") && !hasExtension(clientExt, "EGL_EXT_device_base"))
        return out;
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto queryString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
    if (!queryDevices || !queryString) return out;
    EGLint count = 0;
    if (!queryDevices(0, nullptr, &count) || count <= 0) return out;
    std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
    if (!queryDevices(count, devices.data(), &count)) return out;
    devices.resize(static_cast<size_t>(count));
    for (EGLDeviceEXT d : devices) {
        const char* ext = queryString(d, EGL_EXTENSIONS);
        (hasExtension(ext, "EGL_MESA_device_software") ? out.software : out.hardware).push_back(d);
    }
    return out;
}

class EglGlContext final : public GlContext {
public:
    explicit EglGlContext(EGLDisplay display) : display_(display) {
        if (!eglBindAPI(EGL_OPENGL_API)) fail("EGL cannot bind the desktop OpenGL API");
        const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                                        EGL_NONE};
        EGLConfig config = nullptr;
        EGLint numConfigs = 0;
        if (!eglChooseConfig(display_, configAttribs, &config, 1, &numConfigs) || numConfigs < 1) {
            const EGLint anyGl[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
            if (!eglChooseConfig(display_, anyGl, &config, 1, &numConfigs) || numConfigs < 1) config = nullptr;
        }
#ifndef NDEBUG
        const EGLint debug = EGL_TRUE;
#else
        const EGLint debug = EGL_FALSE;
#endif
        for (const EGLint minor : {5, 3}) {
            const EGLint ctxAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                         4,
                                         EGL_CONTEXT_MINOR_VERSION,
                                         minor,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_CONTEXT_OPENGL_DEBUG,
                                         debug,
                                         EGL_NONE};
            context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, ctxAttribs);
            if (context_ != EGL_NO_CONTEXT) break;
        }
        if (context_ == EGL_NO_CONTEXT) fail("EGL could not create a GL 4.x core context");
        makeCurrent();
        initialiseGl([](const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); });
    }
    ~EglGlContext() override { release(); }
    void makeCurrent() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            fail("EGL could not make its context current (no surfaceless support?)");
    }
    [[nodiscard]] Backend backend() const noexcept override { return Backend::Egl; }

private:
    [[noreturn]] void fail(const std::string& what) {
        const EGLint err = eglGetError();
        release();
        char code[16];
        std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(err));
        throw std::runtime_error(what + " (EGL error " + code + ")");
    }
    void release() noexcept {
        if (display_ == EGL_NO_DISPLAY) return;
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
        eglTerminate(display_);
        display_ = EGL_NO_DISPLAY;
        context_ = EGL_NO_CONTEXT;
    }
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

EGLDisplay initialisedDisplay(EGLenum platform, void* native) {
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) return EGL_NO_DISPLAY;
    EGLDisplay d = getPlatformDisplay(platform, native, nullptr);
    if (d == EGL_NO_DISPLAY) return d;
    EGLint major = 0, minor = 0;
    if (!eglInitialize(d, &major, &minor)) return EGL_NO_DISPLAY;
    return d;
}

} // namespace

bool eglHardwareDeviceAvailable(std::string* why) {
    const EglDevices devices = enumerateDevices();
    if (why)
        *why = std::to_string(devices.hardware.size()) + " hardware and " + std::to_string(devices.software.size()) +
               " software EGL device(s)";
    return !devices.hardware.empty();
}

std::unique_ptr<GlContext> createEglContext() {
    const EglDevices devices = enumerateDevices();
    std::vector<EGLDeviceEXT> ordered = devices.hardware;
    ordered.insert(ordered.end(), devices.software.begin(), devices.software.end());
    std::string lastError = "no EGL device found";
    for (EGLDeviceEXT dev : ordered) {
        EGLDisplay d = initialisedDisplay(EGL_PLATFORM_DEVICE_EXT, dev);
        if (d == EGL_NO_DISPLAY) continue;
        try {
            return std::make_unique<EglGlContext>(d);
        } catch (const std::exception& e) {
            lastError = e.what();
        }
    }
    EGLDisplay d = initialisedDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY);
    if (d != EGL_NO_DISPLAY) return std::make_unique<EglGlContext>(d);
    throw std::runtime_error("EGL: " + lastError);
}

} // namespace renderer
