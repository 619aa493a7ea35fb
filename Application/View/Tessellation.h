#pragma once
// GL-free triangle generators for the fixed-function drawing layer (docs/book-reference.md §1.6): the icosphere, the
// cube and the plane quad. FixedFunctionPrimitives.cpp only feeds these lists to OpenGL, so counts, normals and winding
// are unit-tested without a GPU stack.
//
// Winding convention (left-handed view, GL's default CCW front faces): a front face seen from outside is
// CCW on screen, which for the world-space vertices means Cross(c - a, b - a) points OUTWARD (the book's
// one-sided triangle normal (a - c) x (a - b), docs/book-reference.md §1.6).

#include <array>
#include <vector>

#include "Physics/Geometry/Geometry3D.h"

/// Flat list of triangles: vertex 3i..3i+2 is triangle i; one normal per vertex.
struct TriangleList {
    std::vector<vec3> positions;
    std::vector<vec3> normals;
    int TriangleCount() const { return static_cast<int>(positions.size() / 3); }
};

/// Icosahedron (X = 0.525731112119133606, Z = 0.850650808352039932) subdivided `divisions` times:
/// 20 * 4^divisions triangles. Positions are unit vectors scaled by `radius` (no matrix scale, so normals
/// stay unit); normal = unit position (smooth). divisions < 0 is treated as 0.
TriangleList Icosphere(int divisions, float radius);
/// Box of half extents (ex, ey, ez) centred at the origin: 12 triangles, two per face, face order top (+Y),
/// front (+Z), left (-X), bottom (-Y), back (-Z), right (+X); flat unit face normals.
TriangleList Cube(float ex, float ey, float ez);
/// Corners of the square that draws `plane`: centred at normal * distance, half side `scale`, wound so that
/// Cross(c - a, b - a) points along the plane normal. A zero normal gives four copies of the origin.
std::array<vec3, 4> PlaneQuad(const Plane& plane, float scale);
/// The book's one-sided triangle normal, normalize((a - c) x (a - b)); zero for a degenerate triangle.
vec3 FrontNormal(const vec3& a, const vec3& b, const vec3& c);
