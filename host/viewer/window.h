// window.h - the viewer's window: GLFW (X11), an OpenGL 3.3+ core context
// and its glad function table. Key events go to one callback.
#pragma once

#include <glad/gl.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace viewer {

class Window {
public:
    // Returns nullptr and sets `error` (one sentence) when there is no display
    // to open or no suitable GL context.
    static std::unique_ptr<Window> open(int width, int height, const std::string& title, std::string& error);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GladGLContext& gl() { return gl_; }
    // The proc-address function in the shape ssao_context_desc wants.
    static void (*get_proc(void* user, const char* name))(void);

    // Called with (GLFW key, GLFW action) for every key event.
    void on_key(std::function<void(int, int)> handler) { key_handler_ = std::move(handler); }
    void poll();                       // handles pending window events
    void wait(double seconds);         // sleeps until an event arrives or `seconds` pass
    bool should_close() const;
    void request_size(int width, int height);
    void framebuffer_size(int& width, int& height) const;
    void swap();
    // The back buffer (framebuffer 0) as RGB8, top row first.
    std::vector<uint8_t> read_pixels(int width, int height);
    std::string renderer() const;

private:
    Window() = default;
    GLFWwindow* window_ = nullptr;
    GladGLContext gl_{};
    std::function<void(int, int)> key_handler_;
};

}  // namespace viewer
