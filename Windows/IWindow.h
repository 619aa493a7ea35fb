#pragma once
// Abstract application window (docs/book-reference.md §1.1 IWindow): event hooks a platform loop calls, plus the
// window's state. Instance-based: the book's pseudo-singleton (a global set in the constructor, a second instance
// quitting) is dropped; whoever runs the loop owns the window object. GL-free.

#include <string>

/// The book's mouse codes.
enum class MouseButton { Left = 1, Middle = 2, Right = 3 };

class IWindow {
public:
    /// Defaults as the book: "Platform Window", 800 x 600, target and fixed FPS 30.
    explicit IWindow(std::string title = "Platform Window", int width = 800, int height = 600);
    virtual ~IWindow() = default;
    IWindow(const IWindow&) = delete;
    IWindow& operator=(const IWindow&) = delete;

    // ---- Hooks, all empty by default. ----
    virtual void OnInitialize() {}
    /// Once per output frame, dt in seconds (UI lives here).
    virtual void OnUpdate(float /*deltaTime*/) {}
    /// Once per fixed step, dt in seconds (simulation lives here).
    virtual void OnFixedUpdate(float /*fixedDeltaTime*/) {}
    virtual void OnRender() {}
    virtual void OnShutdown() {}
    virtual void OnResize(int /*width*/, int /*height*/) {}
    /// Cursor position in pixels, origin top-left, y down.
    virtual void OnMouseMove(int /*x*/, int /*y*/) {}
    virtual void OnMouseDown(MouseButton /*button*/) {}
    virtual void OnMouseUp(MouseButton /*button*/) {}
    /// keyCode in 0..255; others are ignored by GLWindow.
    virtual void OnKeyDown(int /*keyCode*/) {}
    virtual void OnKeyUp(int /*keyCode*/) {}

    // ---- State. ----
    void SetTitle(const std::string& title);
    const std::string& GetTitle() const { return title; }
    /// True once after each SetTitle.
    bool GetAndResetTitleDirtyFlag();
    void SetFullScreen(bool value) { fullscreen = value; }
    bool GetFullScreen() const { return fullscreen; }
    /// Stores the new size (clamped to >= 1) and calls OnResize with it.
    void Resize(int width, int height);
    int GetWidth() const { return width; }
    int GetHeight() const { return height; }
    /// Asks the loop to stop after the current frame.
    void Close() { quit = true; }
    bool GetQuitFlag() const { return quit; }
    void MarkAsShown() { shown = true; }
    bool WasWindowShown() const { return shown; }

protected:
    bool quit = false;
    bool fullscreen = false;
    int width;
    int height;
    bool shown = false;
    std::string title;
    bool titleDirty = true;
};
