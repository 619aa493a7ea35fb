#pragma once
// The EGL back end of HeadlessContext: desktop OpenGL 2.1 compatibility through eglBindAPI(EGL_OPENGL_API),
// with no window or surface at all (EGL_KHR_surfaceless_context): the frames are drawn into a framebuffer
// object the context makes for itself. Where Mesa 25.1 and later no longer ship OSMesa, this is the headless
// path. docs/rendering.md, "Back ends", says how the device is chosen and why the goldens pin llvmpipe.

#include <memory>
#include <string>

#include "Platform/GlContext.h"

/// Where an EGL context was made, for the run summary.
struct EglDeviceChoice {
    std::string platform;  ///< "device" (EGL_EXT_platform_device) or "surfaceless" (EGL_MESA_platform_surfaceless)
    std::string device;    ///< the DRM device file of a hardware device, "software" for Mesa's, "" if none
};

/// An EGL context on the first hardware device EGL_EXT_device_enumeration lists (a GPU driver), else on
/// Mesa's software device, else on the surfaceless platform. RGBA8 colour, 24 depth and 8 stencil bits in the
/// framebuffer object, bound before this returns (after CreateHeadlessContext loads GL: see
/// HeadlessContext::AfterGlLoaded). Returns nullptr and sets *error naming the EGL call that failed.
std::unique_ptr<HeadlessContext> CreateEglContext(int width, int height, EglDeviceChoice* choice, std::string* error);
