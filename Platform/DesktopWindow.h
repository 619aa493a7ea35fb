#pragma once
// A desktop window with a current OpenGL 2.1 compatibility context, through GLFW (Debian's libglfw3): the
// windowed platform beside the headless one (HeadlessContext). It knows nothing of demos; input reaches the
// application through DesktopInput, and GL functions are loaded through GLAD when Create succeeds.

#include <memory>
#include <string>

struct GLFWwindow;

/// What the window reports, in window pixels (origin top-left, y down).
class DesktopInput {
public:
    virtual ~DesktopInput() = default;
    virtual void OnCursor(int /*x*/, int /*y*/) {}
    /// button: 1 left, 2 middle, 3 right (the book's codes).
    virtual void OnButton(int /*button*/, bool /*down*/) {}
    /// key: the GLFW key code; only printable ASCII codes (32..126) are meaningful to the book's keyboard state.
    virtual void OnKey(int /*key*/, bool /*down*/) {}
    virtual void OnResize(int /*width*/, int /*height*/) {}
};

class DesktopWindow {
public:
    /// Opens a width x height window titled `title` on the display ($DISPLAY on X11), makes its GL context
    /// current, turns vsync on or off and loads GL. nullptr and *error (naming the step) on failure, for
    /// example when there is no display.
    static std::unique_ptr<DesktopWindow> Create(const std::string& title, int width, int height, bool vsync,
                                                 std::string* error);
    ~DesktopWindow();
    DesktopWindow(const DesktopWindow&) = delete;
    DesktopWindow& operator=(const DesktopWindow&) = delete;

    /// Routes input to `input` (not owned; nullptr stops it). Install before ImGui's GLFW back end, which
    /// chains to these callbacks.
    void SetInput(DesktopInput* input);
    GLFWwindow* Handle() const { return window; }
    bool ShouldClose() const;
    void RequestClose();
    void SetTitle(const std::string& title);
    /// Processes pending events (calls the DesktopInput hooks).
    void PollEvents();
    void SwapBuffers();
    /// Seconds since GLFW started (monotonic).
    static double Seconds();

private:
    explicit DesktopWindow(GLFWwindow* w) : window(w) {}
    GLFWwindow* window = nullptr;
    DesktopInput* input = nullptr;
};
