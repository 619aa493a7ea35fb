#include "Platform/HeadlessContext.h"

#include <glad/gl.h>

#include <cstdlib>

#if PSB_HAVE_EGL
#include "Platform/EglContext.h"
#endif
#if PSB_HAVE_OSMESA
#include "Platform/OSMesaContext.h"
#endif

void PinSoftwareRasterizer() {
    // llvmpipe, not softpipe: the goldens were made with it.
    setenv("GALLIUM_DRIVER", "llvmpipe", 1);
    // The JIT otherwise picks 256-bit AVX code on AVX2 machines and 128-bit SSE elsewhere; the two round
    // differently in places, so pin the narrower one every x86-64 CPU has.
    setenv("LP_NATIVE_VECTOR_WIDTH", "128", 1);
    // Rasteriser threads change speed, not pixels (llvmpipe bins into fixed tiles; frames checked identical
    // for 0, 1 and 3). 0 rasterises on the calling thread, which leaves the second core to the PNG encoder
    // without a hand-off per frame; a caller may override it.
    setenv("LP_NUM_THREADS", "0", 0);
}

const char* ToString(HeadlessBackend backend) {
    switch (backend) {
        case HeadlessBackend::OSMesa:
            return "osmesa";
        case HeadlessBackend::Egl:
            return "egl";
        case HeadlessBackend::Auto:
            break;
    }
    return "auto";
}

bool ParseHeadlessBackend(const std::string& text, HeadlessBackend* out) {
    for (HeadlessBackend b : {HeadlessBackend::Auto, HeadlessBackend::OSMesa, HeadlessBackend::Egl})
        if (text == ToString(b)) {
            *out = b;
            return true;
        }
    return false;
}

bool HeadlessBackendBuilt(HeadlessBackend backend) {
    switch (backend) {
        case HeadlessBackend::OSMesa:
            return PSB_HAVE_OSMESA != 0;
        case HeadlessBackend::Egl:
            return PSB_HAVE_EGL != 0;
        case HeadlessBackend::Auto:
            break;
    }
    return PSB_HAVE_OSMESA != 0 || PSB_HAVE_EGL != 0;
}

namespace {

std::unique_ptr<HeadlessContext> CreateBackend(int width, int height, HeadlessBackend backend, std::string* device,
                                               std::string* error) {
    if (backend == HeadlessBackend::Auto) backend = PSB_HAVE_OSMESA ? HeadlessBackend::OSMesa : HeadlessBackend::Egl;
    if (!HeadlessBackendBuilt(backend)) {
        *error = std::string("this build has no ") + ToString(backend) + " back end";
        return nullptr;
    }
#if PSB_HAVE_OSMESA
    if (backend == HeadlessBackend::OSMesa) return CreateOSMesaContext(width, height, error);
#endif
#if PSB_HAVE_EGL
    EglDeviceChoice choice;
    std::unique_ptr<HeadlessContext> context = CreateEglContext(width, height, &choice, error);
    *device = choice.platform == "device" ? "device " + choice.device : choice.platform;
    return context;
#else
    (void)width, (void)height, (void)device;
    return nullptr;
#endif
}

}  // namespace

std::unique_ptr<HeadlessContext> CreateHeadlessContext(int width, int height, HeadlessInfo* info, std::string* error) {
    return CreateHeadlessContext(width, height, HeadlessBackend::Auto, info, error);
}

std::unique_ptr<HeadlessContext> CreateHeadlessContext(int width, int height, HeadlessBackend backend,
                                                       HeadlessInfo* info, std::string* error) {
    std::string device;
    std::unique_ptr<HeadlessContext> context = CreateBackend(width, height, backend, &device, error);
    if (!context) return nullptr;
    const int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(context->ProcLoader()));
    if (version == 0) {
        *error = "gladLoadGL failed (no GL entry points from " + std::string(context->BackendName()) + ")";
        return nullptr;
    }
    if (GLAD_VERSION_MAJOR(version) < 2 || (GLAD_VERSION_MAJOR(version) == 2 && GLAD_VERSION_MINOR(version) < 1)) {
        *error = "OpenGL 2.1 required, context offers " + std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                 std::to_string(GLAD_VERSION_MINOR(version));
        return nullptr;
    }
    if (!context->AfterGlLoaded(error)) return nullptr;
    GLint depthBits = 0, stencilBits = 0;
    glGetIntegerv(GL_DEPTH_BITS, &depthBits);
    glGetIntegerv(GL_STENCIL_BITS, &stencilBits);
    if (depthBits < 24 || stencilBits < 8) {
        *error = "context has " + std::to_string(depthBits) + " depth bits and " + std::to_string(stencilBits) +
                 " stencil bits; 24 and 8 are required";
        return nullptr;
    }
    if (info) {
        const auto text = [](GLenum name) {
            const GLubyte* s = glGetString(name);
            return s ? std::string(reinterpret_cast<const char*>(s)) : std::string();
        };
        info->backend = context->BackendName();
        info->device = device;
        info->vendor = text(GL_VENDOR);
        info->renderer = text(GL_RENDERER);
        info->version = text(GL_VERSION);
        info->depthBits = depthBits;
        info->stencilBits = stencilBits;
    }
    return context;
}
