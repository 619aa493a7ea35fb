// Screen-to-world picking (book ch. 14 "Unproject" / "GetPickRay", book.md 4.2). Row-vector convention:
// clip = world * view * projection, so a clip point goes back through Inverse(projection), then
// Inverse(view).
#include <cmath>

#include "Geometry3D.h"

namespace {

/// [x y z w] * m for a row vector.
void MultiplyRow(const float in[4], const mat4& m, float out[4]) {
    for (int j = 0; j < 4; ++j) out[j] = in[0] * m[0][j] + in[1] * m[1][j] + in[2] * m[2][j] + in[3] * m[3][j];
}

}  // namespace

/// Pixels (y down, relative to the viewport origin) and depth in [0,1] (clamped; 0 near plane, 1 far plane)
/// back to world space. A non-positive viewport size is treated as 1 pixel. The result is divided by w.
vec3 Unproject(const vec3& viewportPoint, const vec2& viewportOrigin, const vec2& viewportSize, const mat4& view,
               const mat4& projection) {
    const float width = viewportSize.x > 0.0f ? viewportSize.x : 1.0f;
    const float height = viewportSize.y > 0.0f ? viewportSize.y : 1.0f;
    const float u = (viewportPoint.x - viewportOrigin.x) / width;
    const float v = (viewportPoint.y - viewportOrigin.y) / height;
    const float z = std::fmin(std::fmax(viewportPoint.z, 0.0f), 1.0f);
    // NDC: x = 2u - 1, y = 1 - 2v (mouse y points down), z in [0, 1] (D3D-style projection).
    const float ndc[4] = {2.0f * u - 1.0f, 1.0f - 2.0f * v, z, 1.0f};
    float eye[4], world[4];
    MultiplyRow(ndc, Inverse(projection), eye);
    MultiplyRow(eye, Inverse(view), world);
    if (world[3] == 0.0f) return vec3(world[0], world[1], world[2]);
    return vec3(world[0] / world[3], world[1] / world[3], world[2] / world[3]);
}

/// World-space ray from the near-plane point under the pixel toward the far-plane point, unit direction.
Ray GetPickRay(const vec2& viewportPoint, const vec2& viewportOrigin, const vec2& viewportSize, const mat4& view,
               const mat4& projection) {
    const vec3 nearPoint =
        Unproject(vec3(viewportPoint.x, viewportPoint.y, 0.0f), viewportOrigin, viewportSize, view, projection);
    const vec3 farPoint =
        Unproject(vec3(viewportPoint.x, viewportPoint.y, 1.0f), viewportOrigin, viewportSize, view, projection);
    return Ray(nearPoint, farPoint - nearPoint);
}
