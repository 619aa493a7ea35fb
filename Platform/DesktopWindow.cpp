#include "Platform/DesktopWindow.h"

#include <glad/gl.h>
// GLFW after GLAD, and without its own GL header.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace {

std::string lastGlfwError;

void RecordError(int code, const char* description) {
    lastGlfwError = std::string(description ? description : "unknown") + " (GLFW error " + std::to_string(code) + ")";
}

DesktopInput* InputOf(GLFWwindow* w) { return static_cast<DesktopInput*>(glfwGetWindowUserPointer(w)); }

void CursorCallback(GLFWwindow* w, double x, double y) {
    if (DesktopInput* in = InputOf(w)) in->OnCursor(int(x), int(y));
}

void ButtonCallback(GLFWwindow* w, int button, int action, int /*mods*/) {
    DesktopInput* in = InputOf(w);
    if (in == nullptr || (action != GLFW_PRESS && action != GLFW_RELEASE)) return;
    const int code = button == GLFW_MOUSE_BUTTON_LEFT     ? 1
                     : button == GLFW_MOUSE_BUTTON_MIDDLE ? 2
                     : button == GLFW_MOUSE_BUTTON_RIGHT  ? 3
                                                          : 0;
    if (code != 0) in->OnButton(code, action == GLFW_PRESS);
}

void KeyCallback(GLFWwindow* w, int key, int /*scancode*/, int action, int /*mods*/) {
    DesktopInput* in = InputOf(w);
    if (in != nullptr && action != GLFW_REPEAT) in->OnKey(key, action == GLFW_PRESS);
}

void ResizeCallback(GLFWwindow* w, int width, int height) {
    if (DesktopInput* in = InputOf(w)) in->OnResize(width, height);
}

}  // namespace

std::unique_ptr<DesktopWindow> DesktopWindow::Create(const std::string& title, int width, int height, bool vsync,
                                                     std::string* error) {
    glfwSetErrorCallback(&RecordError);
    if (!glfwInit()) {
        *error = "cannot open a window: " + (lastGlfwError.empty() ? std::string("glfwInit failed") : lastGlfwError);
        return nullptr;
    }
    // The book's context: GL 2.1 compatibility, RGBA8, 24 depth and 8 stencil bits, double buffered.
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    glfwWindowHint(GLFW_STENCIL_BITS, 8);
    glfwWindowHint(GLFW_DOUBLEBUFFER, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (window == nullptr) {
        *error = "cannot open a " + std::to_string(width) + "x" + std::to_string(height) + " window: " + lastGlfwError;
        glfwTerminate();
        return nullptr;
    }
    std::unique_ptr<DesktopWindow> result(new DesktopWindow(window));
    glfwMakeContextCurrent(window);
    glfwSwapInterval(vsync ? 1 : 0);
    const int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress));
    if (version == 0 || GLAD_VERSION_MAJOR(version) < 2 ||
        (GLAD_VERSION_MAJOR(version) == 2 && GLAD_VERSION_MINOR(version) < 1)) {
        *error = "the window's context offers no OpenGL 2.1";
        return nullptr;
    }
    return result;
}

DesktopWindow::~DesktopWindow() {
    glfwDestroyWindow(window);
    // No glfwTerminate: it unloads libGL and Mesa's driver, whose one-time allocations then show up in
    // LeakSanitizer as leaks from an unloaded library that no suppression can name. One window per process;
    // the display connection closes at exit.
}

void DesktopWindow::SetInput(DesktopInput* in) {
    input = in;
    glfwSetWindowUserPointer(window, in);
    glfwSetCursorPosCallback(window, &CursorCallback);
    glfwSetMouseButtonCallback(window, &ButtonCallback);
    glfwSetKeyCallback(window, &KeyCallback);
    glfwSetFramebufferSizeCallback(window, &ResizeCallback);
}

bool DesktopWindow::ShouldClose() const { return glfwWindowShouldClose(window) != 0; }
void DesktopWindow::RequestClose() { glfwSetWindowShouldClose(window, GLFW_TRUE); }
void DesktopWindow::SetTitle(const std::string& title) { glfwSetWindowTitle(window, title.c_str()); }
void DesktopWindow::PollEvents() { glfwPollEvents(); }
void DesktopWindow::SwapBuffers() { glfwSwapBuffers(window); }
double DesktopWindow::Seconds() { return glfwGetTime(); }
