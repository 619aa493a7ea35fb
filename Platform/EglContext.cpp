#include "Platform/EglContext.h"

#include <glad/gl.h>
// EGL after GLAD; eglplatform.h with no USE_X11 defined needs no X11 headers.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <vector>

namespace {

std::string Hex(EGLint code) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%04X", unsigned(code));
    return text;
}

bool HasExtension(const char* list, const char* name) {
    if (list == nullptr) return false;
    const std::size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

class EglHeadlessContext final : public HeadlessContext {
public:
    EglHeadlessContext(EGLDisplay d, EGLContext c, int w, int h) : display(d), context(c) {
        width = w;
        height = h;
    }
    ~EglHeadlessContext() override {
        if (framebuffer != 0 && glad_glDeleteFramebuffers != nullptr) {
            glDeleteFramebuffers(1, &framebuffer);
            glDeleteRenderbuffers(2, renderbuffers);
        }
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display, context);
        // No eglTerminate: it unloads Mesa's driver, whose few one-time allocations then show up in
        // LeakSanitizer as leaks from an unloaded library that no suppression can name. The display is
        // process-wide; leaving it initialised costs nothing, and a later eglInitialize reuses it.
    }

    const char* BackendName() const override { return "egl"; }
    HeadlessProcLoader ProcLoader() const override { return &Resolve; }
    bool MakeCurrent() override { return eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context) == EGL_TRUE; }

    /// The context has no default framebuffer: make an RGBA8 + depth 24 / stencil 8 framebuffer object and
    /// leave it bound for drawing and glReadPixels.
    bool AfterGlLoaded(std::string* error) override {
        if (!GLAD_GL_ARB_framebuffer_object || !GLAD_GL_EXT_packed_depth_stencil) {
            *error = "EGL context lacks GL_ARB_framebuffer_object or GL_EXT_packed_depth_stencil";
            return false;
        }
        glGenFramebuffers(1, &framebuffer);
        glGenRenderbuffers(2, renderbuffers);
        glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers[0]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
        glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers[1]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers[0]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, renderbuffers[1]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, renderbuffers[1]);
        const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE) {
            *error = "framebuffer object of " + std::to_string(width) + "x" + std::to_string(height) +
                     " is incomplete (status " + Hex(EGLint(status)) + ")";
            return false;
        }
        glDrawBuffer(GL_COLOR_ATTACHMENT0);
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        glViewport(0, 0, width, height);
        return true;
    }

private:
    static HeadlessProc Resolve(const char* name) { return reinterpret_cast<HeadlessProc>(eglGetProcAddress(name)); }

    EGLDisplay display;
    EGLContext context;
    GLuint framebuffer = 0;
    GLuint renderbuffers[2] = {0, 0};
};

/// The display of the first hardware device, else of Mesa's software device, else the surfaceless platform.
EGLDisplay OpenDisplay(EglDeviceChoice* choice, std::string* error) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (getPlatformDisplay == nullptr) {
        *error = "EGL has no eglGetPlatformDisplayEXT (EGL_EXT_platform_base)";
        return EGL_NO_DISPLAY;
    }
    if (HasExtension(clientExtensions, "EGL_EXT_platform_device") &&
        HasExtension(clientExtensions, "EGL_EXT_device_enumeration")) {
        auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        auto queryDeviceString =
            reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
        EGLint count = 0;
        std::vector<EGLDeviceEXT> devices(16);
        if (queryDevices != nullptr && queryDevices(EGLint(devices.size()), devices.data(), &count) && count > 0) {
            devices.resize(std::size_t(count));
            EGLDeviceEXT software = nullptr, hardware = nullptr;
            std::string hardwareFile;
            for (EGLDeviceEXT device : devices) {
                const char* ext = queryDeviceString ? queryDeviceString(device, EGL_EXTENSIONS) : nullptr;
                if (HasExtension(ext, "EGL_MESA_device_software")) {
                    if (software == nullptr) software = device;
                } else if (hardware == nullptr && HasExtension(ext, "EGL_EXT_device_drm")) {
                    hardware = device;
                    const char* file = queryDeviceString(device, EGL_DRM_DEVICE_FILE_EXT);
                    hardwareFile = file ? file : "drm";
                }
            }
            EGLDeviceEXT pick = hardware ? hardware : software;
            if (pick != nullptr) {
                EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, pick, nullptr);
                if (display != EGL_NO_DISPLAY) {
                    choice->platform = "device";
                    choice->device = hardware ? hardwareFile : "software";
                    return display;
                }
            }
        }
    }
    if (HasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display != EGL_NO_DISPLAY) {
            choice->platform = "surfaceless";
            choice->device.clear();
            return display;
        }
    }
    *error = "no EGL device (EGL_EXT_platform_device) and no surfaceless platform (EGL_MESA_platform_surfaceless)";
    return EGL_NO_DISPLAY;
}

}  // namespace

std::unique_ptr<HeadlessContext> CreateEglContext(int width, int height, EglDeviceChoice* choice, std::string* error) {
    EglDeviceChoice local;
    if (choice == nullptr) choice = &local;
    EGLDisplay display = OpenDisplay(choice, error);
    if (display == EGL_NO_DISPLAY) return nullptr;
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) {
        *error = "eglInitialize failed (" + Hex(eglGetError()) + ")";
        return nullptr;
    }
    const auto fail = [&](const std::string& what) {
        *error = what + " (" + Hex(eglGetError()) + ")";
        return nullptr;
    };
    if (!HasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"))
        return fail("EGL display lacks EGL_KHR_surfaceless_context");
    if (!eglBindAPI(EGL_OPENGL_API)) return fail("eglBindAPI(EGL_OPENGL_API) failed: no desktop OpenGL");
    // The config only names the API: the colour, depth and stencil buffers are the framebuffer object's.
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE,
                                    EGL_OPENGL_BIT,
                                    EGL_SURFACE_TYPE,
                                    EGL_PBUFFER_BIT,
                                    EGL_RED_SIZE,
                                    8,
                                    EGL_GREEN_SIZE,
                                    8,
                                    EGL_BLUE_SIZE,
                                    8,
                                    EGL_ALPHA_SIZE,
                                    8,
                                    EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    if (!eglChooseConfig(display, configAttribs, &config, 1, &configs) || configs < 1)
        return fail("eglChooseConfig found no RGBA8 desktop OpenGL config");
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 2, EGL_CONTEXT_MINOR_VERSION, 1, EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttribs);
    if (context == EGL_NO_CONTEXT) return fail("eglCreateContext(OpenGL 2.1 compatibility) failed");
    auto headless = std::make_unique<EglHeadlessContext>(display, context, width, height);
    if (!headless->MakeCurrent()) {
        *error = "eglMakeCurrent(surfaceless) failed (" + Hex(eglGetError()) + ")";
        return nullptr;
    }
    return headless;
}
