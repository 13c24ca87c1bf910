#include "window.h"

#include <GLFW/glfw3.h>

#include <algorithm>

namespace viewer {

namespace {

// GLFW reports failures through a callback; the newest description is kept
// for the one-line error.
std::string g_glfw_error;

void record_error(int /*code*/, const char* description) { g_glfw_error = description ? description : "unknown error"; }

GLADapiproc load(const char* name) { return reinterpret_cast<GLADapiproc>(glfwGetProcAddress(name)); }

}  // namespace

std::unique_ptr<Window> Window::open(int width, int height, const std::string& title, std::string& error) {
    glfwSetErrorCallback(record_error);
    if (!glfwInit()) {
        error = "cannot open a display (" + g_glfw_error + "); run it on a desktop, or headless under xvfb-run";
        return nullptr;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    std::unique_ptr<Window> w(new Window());
    w->window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!w->window_) {
        error = "cannot open a window with an OpenGL 3.3 core context (" + g_glfw_error + ")";
        return nullptr;   // ~Window terminates GLFW
    }
    glfwMakeContextCurrent(w->window_);
    if (gladLoadGLContext(&w->gl_, load) == 0) {
        error = "glad could not load OpenGL through glfwGetProcAddress";
        return nullptr;
    }
    glfwSetWindowUserPointer(w->window_, w.get());
    glfwSetKeyCallback(w->window_, [](GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
        auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
        if (self && self->key_handler_) self->key_handler_(key, action);
    });
    return w;
}

Window::~Window() {
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

void (*Window::get_proc(void* /*user*/, const char* name))(void) { return glfwGetProcAddress(name); }

void Window::poll() { glfwPollEvents(); }

void Window::wait(double seconds) { glfwWaitEventsTimeout(seconds); }

bool Window::should_close() const { return glfwWindowShouldClose(window_) != 0; }

void Window::request_size(int width, int height) { glfwSetWindowSize(window_, width, height); }

void Window::framebuffer_size(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }

void Window::swap() { glfwSwapBuffers(window_); }

std::vector<uint8_t> Window::read_pixels(int width, int height) {
    auto& gl = gl_;
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    gl.ReadBuffer(GL_BACK);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    std::vector<uint8_t> bottom_up(static_cast<size_t>(width) * static_cast<size_t>(height) * 3);
    gl.ReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bottom_up.data());
    std::vector<uint8_t> top_down(bottom_up.size());
    const size_t row = static_cast<size_t>(width) * 3;
    for (int y = 0; y < height; ++y)
        std::copy_n(bottom_up.begin() + static_cast<ptrdiff_t>(static_cast<size_t>(y) * row), row,
                    top_down.begin() + static_cast<ptrdiff_t>(static_cast<size_t>(height - 1 - y) * row));
    return top_down;
}

std::string Window::renderer() const {
    const GLubyte* r = gl_.GetString(GL_RENDERER);
    return r ? reinterpret_cast<const char*>(r) : "?";
}

}  // namespace viewer
