#pragma once
// The interface every headless GL back end implements (Platform/OSMesaContext.h, Platform/EglContext.h); the
// factory that picks one is Platform/HeadlessContext.h. On its own so the back ends do not include their factory.

#include <string>

/// The GL function loader type GLAD 2's gladLoadGL expects (kept free of GL headers here).
using HeadlessProc = void (*)();
using HeadlessProcLoader = HeadlessProc (*)(const char* name);

class HeadlessContext {
public:
    virtual ~HeadlessContext() = default;
    /// Short name of the back end ("osmesa").
    virtual const char* BackendName() const = 0;
    /// Resolves a GL entry point of this context; nullptr if unknown.
    virtual HeadlessProcLoader ProcLoader() const = 0;
    /// Makes the context current on the calling thread. False on failure.
    virtual bool MakeCurrent() = 0;
    /// Runs once the GL functions are loaded (e.g. to make and bind a framebuffer object). False and *error
    /// on failure.
    virtual bool AfterGlLoaded(std::string* /*error*/) { return true; }
    int Width() const { return width; }
    int Height() const { return height; }

protected:
    int width = 0;
    int height = 0;
};
