#define GLFW_INCLUDE_NONE
#include "context.h"

#include <GLFW/glfw3.h>

#include <stdexcept>

namespace renderer {

namespace {
std::string g_glfwError;
void onGlfwError(int, const char* description) { g_glfwError = description ? description : "unknown"; }
} // namespace

GlfwWindowContext::GlfwWindowContext(int width, int height, const std::string& title) {
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) throw std::runtime_error("cannot open a window: " + g_glfwError);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
#ifndef NDEBUG
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
#endif
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
        window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    }
    if (!window_) {
        glfwTerminate();
        throw std::runtime_error("cannot open a GL 4.3+ window: " + g_glfwError);
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
    try {
        initialiseGl([](const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); });
    } catch (...) {
        glfwDestroyWindow(window_);
        glfwTerminate();
        throw;
    }
}

GlfwWindowContext::~GlfwWindowContext() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

void GlfwWindowContext::makeCurrent() { glfwMakeContextCurrent(window_); }

} // namespace renderer
