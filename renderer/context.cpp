#include "context.h"

#include <cstdlib>
#include <cstring>
#include <mutex>
#include <stdexcept>

namespace renderer {

Backend parseBackend(std::string_view name) {
    if (name == "auto") return Backend::Auto;
    if (name == "glfw") return Backend::Glfw;
    if (name == "osmesa") return Backend::OSMesa;
    if (name == "egl") return Backend::Egl;
    throw std::invalid_argument("unknown backend '" + std::string(name) + "' (valid: auto, glfw, osmesa, egl)");
}

std::string_view backendName(Backend b) noexcept {
    switch (b) {
    case Backend::Auto: return "auto";
    case Backend::Glfw: return "glfw";
    case Backend::OSMesa: return "osmesa";
    case Backend::Egl: return "egl";
    }
    return "?";
}

namespace {
std::mutex g_errorMutex;
std::string g_errors;

void APIENTRY onDebugMessage(GLenum, GLenum type, GLuint, GLenum severity, GLsizei, const GLchar* message,
                             const void*) {
    if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH) return;
    std::lock_guard lock(g_errorMutex);
    if (!g_errors.empty()) g_errors += "; ";
    g_errors += message ? message : "(no message)";
}

bool debugOutputWanted() {
#ifndef NDEBUG
    return true;
#else
    const char* env = std::getenv("SHADOWSCOPE_GL_DEBUG");
    return env && std::strcmp(env, "1") == 0;
#endif
}
} // namespace

std::string takeGlErrors() {
    std::string out;
    if (glGetError)
        for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError())
            out += (out.empty() ? "" : "; ") + std::string("glGetError 0x") + [&] {
                char buf[16];
                std::snprintf(buf, sizeof buf, "%04x", e);
                return std::string(buf);
            }();
    std::lock_guard lock(g_errorMutex);
    if (!g_errors.empty()) out += (out.empty() ? "" : "; ") + g_errors;
    g_errors.clear();
    return out;
}

void GlContext::initialiseGl(gl::ProcAddressFn getProc) {
    if (const char* missing = gl::loadFunctions(getProc))
        throw std::runtime_error(std::string("GL function ") + missing + " is not available in this context");
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const auto* v = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    renderer_ = r ? r : "unknown";
    version_ = v ? v : "unknown";
    if (major * 10 + minor < 43)
        throw std::runtime_error("GL 4.3 core or newer is needed, got " + version_ + " (" + renderer_ + ")");
    if (debugOutputWanted()) {
        glEnable(GL_DEBUG_OUTPUT);
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
        glDebugMessageCallback(onDebugMessage, nullptr);
    }
    (void)takeGlErrors();
}

std::unique_ptr<GlContext> createHeadlessContext(Backend backend) {
    switch (backend) {
    case Backend::OSMesa: return createOSMesaContext();
    case Backend::Egl: return createEglContext();
    case Backend::Auto: return eglHardwareDeviceAvailable() ? createEglContext() : createOSMesaContext();
    case Backend::Glfw: break;
    }
    throw std::runtime_error("backend 'glfw' needs a window; use osmesa or egl for headless work");
}

} // namespace renderer

namespace renderer {
void beginWindowFrame(int w, int h) noexcept {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, w, h);
    glClearColor(0.09f, 0.09f, 0.1f, 1.f);
    glClear(GL_COLOR_BUFFER_BIT);
}
} // namespace renderer
