#pragma once
// GL 4.x core contexts: a GLFW window (GUI), OSMesa (headless, llvmpipe) or EGL (headless,
// device platform: a GPU if there is one, else Mesa's software device / surfaceless).
#include "gl/gl_api.h"

#include <memory>
#include <string>
#include <string_view>

struct GLFWwindow;

namespace renderer {

enum class Backend { Auto, Glfw, OSMesa, Egl };

/// "auto", "glfw", "osmesa", "egl"; throws std::invalid_argument otherwise.
[[nodiscard]] Backend parseBackend(std::string_view name);
[[nodiscard]] std::string_view backendName(Backend b) noexcept;

class GlContext {
public:
    virtual ~GlContext() = default;
    virtual void makeCurrent() = 0;
    [[nodiscard]] virtual Backend backend() const noexcept = 0;
    /// GL_RENDERER, GL_VERSION of this context (valid after construction).
    [[nodiscard]] const std::string& rendererString() const noexcept { return renderer_; }
    [[nodiscard]] const std::string& versionString() const noexcept { return version_; }

protected:
    /// Loads GL through `getProc`, checks for GL ≥ 4.3 core, enables debug output in debug
    /// builds. Throws std::runtime_error with a one-line reason.
    void initialiseGl(gl::ProcAddressFn getProc);

private:
    std::string renderer_, version_;
};

/// True when EGL exposes a hardware (non-software) device; `why` says what was found.
[[nodiscard]] bool eglHardwareDeviceAvailable(std::string* why = nullptr);

/// Headless context for Backend::OSMesa or Backend::Egl; Auto picks EGL when a hardware
/// device exists, else OSMesa. Throws std::runtime_error with a one-line reason.
[[nodiscard]] std::unique_ptr<GlContext> createHeadlessContext(Backend backend);
[[nodiscard]] std::unique_ptr<GlContext> createOSMesaContext();
[[nodiscard]] std::unique_ptr<GlContext> createEglContext();

/// A GLFW window with a GL context. Throws std::runtime_error when no window can be made.
class GlfwWindowContext final : public GlContext {
public:
    GlfwWindowContext(int width, int height, const std::string& title);
    ~GlfwWindowContext() override;
    void makeCurrent() override;
    [[nodiscard]] Backend backend() const noexcept override { return Backend::Glfw; }
    [[nodiscard]] GLFWwindow* window() const noexcept { return window_; }

private:
    GLFWwindow* window_ = nullptr;
};

/// GL debug messages of severity "high" or type "error" seen since the last call (debug output
/// is on in debug builds and whenever SHADOWSCOPE_GL_DEBUG=1), plus any glGetError code.
/// Tests fail on a non-empty result.
[[nodiscard]] std::string takeGlErrors();

} // namespace renderer

namespace renderer {
/// Clears the window's default framebuffer before the UI draws into it.
void beginWindowFrame(int framebufferWidth, int framebufferHeight) noexcept;
} // namespace renderer
