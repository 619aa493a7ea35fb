#pragma once
// Fixed-function (OpenGL 2.1 immediate mode) drawing of the primitives, docs/book-reference.md §1.6. The only layer
// besides Platform/ and Windows/ that includes GL. Colours come from the light (docs/book-reference.md §1.5), not
// glColor.

#include <array>
#include <vector>

#include "Physics/Geometry/Geometry3D.h"

void Render(const Point& point);
void Render(const Line& line);
/// A line from the origin to origin + direction * 50000.
void Render(const Ray& ray);
/// Twice-subdivided icosahedron (320 triangles), smooth normals.
void Render(const Sphere& sphere);
void Render(const AABB& aabb);
/// Scale(size) * FromMat3(orientation) * Translation(position), unit cube of 12 triangles, flat normals.
void Render(const OBB& obb);
void Render(const Plane& plane);
void Render(const Plane& plane, float scale);
/// Both windings, no normal.
void Render(const Triangle& triangle);
/// oneSided: normal (a-c)x(a-b), a single triangle a,b,c (the cloth uses this).
void Render(const Triangle& triangle, bool oneSided);
/// Only if colliding: red contact points, green contact->contact+normal*depth lines, a blue unit normal line
/// from the contact centroid.
void Render(const CollisionManifold& manifold);
void Render(const std::vector<Line>& edges);
void Render(const std::array<Line, 12>& edges);
void Render(const Mesh& mesh);
void Render(const Model& model);

void FixedFunctionSphere(int divisions = 2, float radius = 1.0f);
void FixedFunctionCube(float extentsX = 1.0f, float extentsY = 1.0f, float extentsZ = 1.0f);
/// Unit axes: +X red, +Y green, +Z blue; lighting off, depth test off while drawing; state restored.
void FixedFunctionOrigin(bool depthTest = false, bool twoSided = false);

/// Sets GL_LIGHT0's ambient and diffuse (alpha 0, specular 0): how the book colours lit geometry.
void SetLightColors(const vec3& ambient, const vec3& diffuse);
/// Directional light position (w = 0), transformed by the current MODELVIEW.
void SetLightDirection(const vec3& direction);
