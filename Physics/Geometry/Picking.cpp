// Screen-to-world picking (book ch. 14 "Unproject" / "GetPickRay", docs/book-reference.md §4.2). Row-vector convention:
// clip = world * view * projection, so a clip point goes back through Inverse(projection), then
// Inverse(view).
#include <cmath>
#include <utility>

#include "Physics/Geometry/Geometry3D.h"

namespace {

/// 4x4 in double precision, row-major like mat4.
struct Mat4d {
    double m[4][4];
};

Mat4d ToDouble(const mat4& a) {
    Mat4d r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = a[i][j];
    return r;
}

/// Gauss-Jordan inverse with partial pivoting. Returns false only for an exactly singular matrix, so a valid
/// projection with a tiny determinant still inverts (erratum 5.2-10: the book's Inverse returns identity when
/// |det| <= 0.005, which silently breaks picking for a near plane below ~0.0022).
bool Invert(Mat4d a, Mat4d* out) {
    Mat4d inv{};
    for (int i = 0; i < 4; ++i) inv.m[i][i] = 1.0;
    for (int col = 0; col < 4; ++col) {
        int pivot = col;
        for (int r = col + 1; r < 4; ++r)
            if (std::fabs(a.m[r][col]) > std::fabs(a.m[pivot][col])) pivot = r;
        if (a.m[pivot][col] == 0.0) return false;
        for (int j = 0; j < 4; ++j) {
            std::swap(a.m[col][j], a.m[pivot][j]);
            std::swap(inv.m[col][j], inv.m[pivot][j]);
        }
        const double scale = 1.0 / a.m[col][col];
        for (int j = 0; j < 4; ++j) {
            a.m[col][j] *= scale;
            inv.m[col][j] *= scale;
        }
        for (int r = 0; r < 4; ++r) {
            if (r == col) continue;
            const double f = a.m[r][col];
            for (int j = 0; j < 4; ++j) {
                a.m[r][j] -= f * a.m[col][j];
                inv.m[r][j] -= f * inv.m[col][j];
            }
        }
    }
    *out = inv;
    return true;
}

/// [x y z w] * m for a row vector.
void MultiplyRow(const double in[4], const Mat4d& m, double out[4]) {
    for (int j = 0; j < 4; ++j) out[j] = in[0] * m.m[0][j] + in[1] * m.m[1][j] + in[2] * m.m[2][j] + in[3] * m.m[3][j];
}

}  // namespace

/// Pixels (y down, relative to the viewport origin) and depth in [0,1] (clamped; 0 near plane, 1 far plane)
/// back to world space. A non-positive viewport size is treated as 1 pixel. The inverses are computed in double
/// precision without a determinant threshold; an exactly singular view or projection returns the origin.
vec3 Unproject(const vec3& viewportPoint, const vec2& viewportOrigin, const vec2& viewportSize, const mat4& view,
               const mat4& projection) {
    const double width = viewportSize.x > 0.0f ? viewportSize.x : 1.0;
    const double height = viewportSize.y > 0.0f ? viewportSize.y : 1.0;
    const double u = (static_cast<double>(viewportPoint.x) - viewportOrigin.x) / width;
    const double v = (static_cast<double>(viewportPoint.y) - viewportOrigin.y) / height;
    const double z = std::fmin(std::fmax(static_cast<double>(viewportPoint.z), 0.0), 1.0);
    // NDC: x = 2u - 1, y = 1 - 2v (mouse y points down), z in [0, 1] (D3D-style projection).
    const double ndc[4] = {2.0 * u - 1.0, 1.0 - 2.0 * v, z, 1.0};
    Mat4d invProj, invView;
    if (!Invert(ToDouble(projection), &invProj) || !Invert(ToDouble(view), &invView)) return vec3(0, 0, 0);
    double eye[4], world[4];
    MultiplyRow(ndc, invProj, eye);
    MultiplyRow(eye, invView, world);
    const double w = world[3] != 0.0 ? world[3] : 1.0;
    return vec3(static_cast<float>(world[0] / w), static_cast<float>(world[1] / w), static_cast<float>(world[2] / w));
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
