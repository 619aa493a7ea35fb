#include "Platform/OSMesaContext.h"

#include <GL/osmesa.h>

#include <vector>

namespace {

class OSMesaHeadlessContext final : public HeadlessContext {
public:
    OSMesaHeadlessContext(OSMesaContext context, int w, int h) : ctx(context), pixels(size_t(w) * size_t(h) * 4) {
        width = w;
        height = h;
    }
    ~OSMesaHeadlessContext() override { OSMesaDestroyContext(ctx); }

    const char* BackendName() const override { return "osmesa"; }
    HeadlessProcLoader ProcLoader() const override { return &Resolve; }
    bool MakeCurrent() override {
        return OSMesaMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, width, height) == GL_TRUE;
    }

private:
    static HeadlessProc Resolve(const char* name) { return reinterpret_cast<HeadlessProc>(OSMesaGetProcAddress(name)); }

    OSMesaContext ctx;
    std::vector<unsigned char> pixels;  // the colour buffer OSMesa renders into
};

}  // namespace

std::unique_ptr<HeadlessContext> CreateOSMesaContext(int width, int height, std::string* error) {
    GLint maxSize[2] = {0, 0};
    // Attribute form so the profile and version are explicit: GL 2.1 compatibility, RGBA, 24 depth, 8 stencil.
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           24,
                           OSMESA_STENCIL_BITS,
                           8,
                           OSMESA_ACCUM_BITS,
                           0,
                           OSMESA_PROFILE,
                           OSMESA_COMPAT_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           2,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           1,
                           0};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!ctx) ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
    if (!ctx) {
        *error = "OSMesaCreateContextExt(RGBA, depth 24, stencil 8) failed";
        return nullptr;
    }
    auto context = std::make_unique<OSMesaHeadlessContext>(ctx, width, height);
    if (!context->MakeCurrent()) {
        *error = "OSMesaMakeCurrent failed for a " + std::to_string(width) + "x" + std::to_string(height) + " buffer";
        return nullptr;
    }
    OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &maxSize[0]);
    OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &maxSize[1]);
    if (width > maxSize[0] || height > maxSize[1]) {
        *error = "size " + std::to_string(width) + "x" + std::to_string(height) + " exceeds OSMesa's maximum " +
                 std::to_string(maxSize[0]) + "x" + std::to_string(maxSize[1]);
        return nullptr;
    }
    return context;
}
