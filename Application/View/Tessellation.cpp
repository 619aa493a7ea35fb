#include "Application/View/Tessellation.h"

#include <cmath>

namespace {

// Icosahedron constants (docs/book-reference.md §1.6): the 12 vertices are the cyclic permutations of (0, ±X, ±Z), unit
// length.
constexpr float kIcoX = 0.525731112119133606f;
constexpr float kIcoZ = 0.850650808352039932f;

void PushTriangle(TriangleList* out, const vec3& a, const vec3& b, const vec3& c, const vec3& na, const vec3& nb,
                  const vec3& nc) {
    out->positions.push_back(a);
    out->positions.push_back(b);
    out->positions.push_back(c);
    out->normals.push_back(na);
    out->normals.push_back(nb);
    out->normals.push_back(nc);
}

/// Orders (a, b, c) so that Cross(c - a, b - a) points along `outward`.
void OrientOutward(const vec3& outward, vec3* a, vec3* b, vec3* c) {
    if (Dot(Cross(*c - *a, *b - *a), outward) < 0.0f) {
        const vec3 t = *b;
        *b = *c;
        *c = t;
    }
}

/// The 20 faces, found as the vertex triples whose three edges all have the icosahedron's edge length 2X
/// (no hand-typed index table), each oriented outward.
std::vector<std::array<vec3, 3>> IcosahedronFaces() {
    const vec3 v[12] = {{-kIcoX, 0, kIcoZ}, {kIcoX, 0, kIcoZ},  {-kIcoX, 0, -kIcoZ}, {kIcoX, 0, -kIcoZ},
                        {0, kIcoZ, kIcoX},  {0, kIcoZ, -kIcoX}, {0, -kIcoZ, kIcoX},  {0, -kIcoZ, -kIcoX},
                        {kIcoZ, kIcoX, 0},  {-kIcoZ, kIcoX, 0}, {kIcoZ, -kIcoX, 0},  {-kIcoZ, -kIcoX, 0}};
    const float edgeSq = 4.0f * kIcoX * kIcoX;
    auto isEdge = [&](int i, int j) { return std::fabs(MagnitudeSq(v[i] - v[j]) - edgeSq) < 1e-3f; };
    std::vector<std::array<vec3, 3>> faces;
    for (int i = 0; i < 12; ++i)
        for (int j = i + 1; j < 12; ++j)
            for (int k = j + 1; k < 12; ++k) {
                if (!isEdge(i, j) || !isEdge(j, k) || !isEdge(i, k)) continue;
                vec3 a = v[i], b = v[j], c = v[k];
                OrientOutward(a + b + c, &a, &b, &c);
                faces.push_back({a, b, c});
            }
    return faces;
}

}  // namespace

vec3 FrontNormal(const vec3& a, const vec3& b, const vec3& c) {
    const vec3 n = Cross(a - c, a - b);
    const float len = Magnitude(n);
    if (!(len > 0.0f)) return vec3();
    return n * (1.0f / len);
}

TriangleList Icosphere(int divisions, float radius) {
    std::vector<std::array<vec3, 3>> faces = IcosahedronFaces();
    for (int d = 0; d < divisions; ++d) {
        // Each face splits into four through its edge midpoints pushed back onto the unit sphere; the four
        // children keep the parent's winding.
        std::vector<std::array<vec3, 3>> next;
        next.reserve(faces.size() * 4);
        for (const auto& f : faces) {
            const vec3 ab = Normalized(f[0] + f[1]);
            const vec3 bc = Normalized(f[1] + f[2]);
            const vec3 ca = Normalized(f[2] + f[0]);
            next.push_back({f[0], ab, ca});
            next.push_back({f[1], bc, ab});
            next.push_back({f[2], ca, bc});
            next.push_back({ab, bc, ca});
        }
        faces.swap(next);
    }
    TriangleList out;
    out.positions.reserve(faces.size() * 3);
    out.normals.reserve(faces.size() * 3);
    for (const auto& f : faces) PushTriangle(&out, f[0] * radius, f[1] * radius, f[2] * radius, f[0], f[1], f[2]);
    return out;
}

TriangleList Cube(float ex, float ey, float ez) {
    // Face normal, then two in-plane axes spanning the face.
    struct Face {
        vec3 n, u, v;
    };
    const Face faces[6] = {
        {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},   // top
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},   // front
        {{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}},  // left
        {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},  // bottom
        {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}},  // back
        {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},   // right
    };
    const vec3 extents(ex, ey, ez);
    TriangleList out;
    out.positions.reserve(36);
    out.normals.reserve(36);
    for (const Face& f : faces) {
        vec3 p0 = f.n - f.u - f.v, p1 = f.n + f.u - f.v, p2 = f.n + f.u + f.v, p3 = f.n - f.u + f.v;
        if (Dot(Cross(p2 - p0, p1 - p0), f.n) < 0.0f) {
            const vec3 t = p1;
            p1 = p3;
            p3 = t;
        }
        p0 = p0 * extents;
        p1 = p1 * extents;
        p2 = p2 * extents;
        p3 = p3 * extents;
        PushTriangle(&out, p0, p1, p2, f.n, f.n, f.n);
        PushTriangle(&out, p0, p2, p3, f.n, f.n, f.n);
    }
    return out;
}

std::array<vec3, 4> PlaneQuad(const Plane& plane, float scale) {
    const float len = Magnitude(plane.normal);
    if (!(len > 0.0f)) return {vec3(), vec3(), vec3(), vec3()};
    const vec3 n = plane.normal * (1.0f / len);
    const vec3 centre = plane.normal * plane.distance;
    // Any axis not parallel to n gives the first tangent.
    const vec3 helper = std::fabs(n.y) < 0.9f ? vec3(0, 1, 0) : vec3(1, 0, 0);
    const vec3 u = Normalized(Cross(helper, n)) * scale;
    const vec3 v = Normalized(Cross(n, u)) * scale;
    std::array<vec3, 4> q = {centre - u - v, centre + u - v, centre + u + v, centre - u + v};
    if (Dot(Cross(q[2] - q[0], q[1] - q[0]), n) < 0.0f) {
        const vec3 t = q[1];
        q[1] = q[3];
        q[3] = t;
    }
    return q;
}
