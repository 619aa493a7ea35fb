#pragma once
// A current OpenGL 2.1 compatibility context without a window, rendering into an off-screen colour buffer.
// Two back ends sit behind this interface: OSMesa (Debian 12 ships it; Mesa 25.1 dropped it upstream) and EGL
// with a framebuffer object (Platform/EglContext.h). Either can be left out of the build; docs/rendering.md,
// "Back ends".

#include <memory>
#include <string>

#include "Platform/GlContext.h"

/// What CreateHeadlessContext found once the context was current (for the summary, docs and tests).
struct HeadlessInfo {
    std::string backend;   ///< "osmesa" or "egl"
    std::string device;    ///< EGL: "device <file>", "device software" or "surfaceless"; "" for OSMesa
    std::string vendor;    ///< glGetString(GL_VENDOR), e.g. "Mesa"
    std::string renderer;  ///< glGetString(GL_RENDERER), e.g. "llvmpipe (LLVM 15.0.6, 128 bits)"
    std::string version;   ///< glGetString(GL_VERSION)
    int depthBits = 0;
    int stencilBits = 0;
};

/// Pins what makes Mesa's software rasteriser reproducible across machines: GALLIUM_DRIVER=llvmpipe and
/// LP_NATIVE_VECTOR_WIDTH=128 (overwritten), LP_NUM_THREADS=0 (only if unset; it does not change pixels).
/// Must run before the first context is created. Mesa 22.3's libOSMesa reads all three.
void PinSoftwareRasterizer();

/// Which back end makes the context. Auto: OSMesa when it is built in, else EGL.
enum class HeadlessBackend { Auto, OSMesa, Egl };

/// "auto", "osmesa", "egl".
const char* ToString(HeadlessBackend backend);
/// Parses "auto", "osmesa" or "egl"; false for anything else.
bool ParseHeadlessBackend(const std::string& text, HeadlessBackend* out);
/// True if this build contains the back end (Auto: if it contains any).
bool HeadlessBackendBuilt(HeadlessBackend backend);

/// Creates a width x height RGBA context (24 depth bits, 8 stencil bits, GL 2.1 compatibility), makes it
/// current, loads the GL functions through GLAD and checks the depth and stencil bits it got.
/// Returns nullptr and sets *error (naming the step that failed) on failure.
std::unique_ptr<HeadlessContext> CreateHeadlessContext(int width, int height, HeadlessBackend backend,
                                                       HeadlessInfo* info, std::string* error);
/// The same with HeadlessBackend::Auto.
std::unique_ptr<HeadlessContext> CreateHeadlessContext(int width, int height, HeadlessInfo* info, std::string* error);
