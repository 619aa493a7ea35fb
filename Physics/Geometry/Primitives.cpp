// Small helpers of the primitive types (Geometry3D.h).
#include <cfloat>
#include <cmath>

#include "Physics/Geometry/Geometry3D.h"

float Length(const Line& line) { return Magnitude(line.start - line.end); }
float LengthSq(const Line& line) { return MagnitudeSq(line.start - line.end); }

Ray FromPoints(const Point& from, const Point& to) { return Ray(from, to - from); }

vec3 GetMin(const AABB& aabb) {
    const vec3 p1 = aabb.position + aabb.size;
    const vec3 p2 = aabb.position - aabb.size;
    return {std::fmin(p1.x, p2.x), std::fmin(p1.y, p2.y), std::fmin(p1.z, p2.z)};
}
vec3 GetMax(const AABB& aabb) {
    const vec3 p1 = aabb.position + aabb.size;
    const vec3 p2 = aabb.position - aabb.size;
    return {std::fmax(p1.x, p2.x), std::fmax(p1.y, p2.y), std::fmax(p1.z, p2.z)};
}
AABB FromMinMax(const vec3& min, const vec3& max) { return AABB((min + max) * 0.5f, (max - min) * 0.5f); }

float PlaneEquation(const Point& point, const Plane& plane) { return Dot(point, plane.normal) - plane.distance; }

void ResetRaycastResult(RaycastResult* outResult) {
    if (outResult == nullptr) return;
    outResult->t = -1.0f;
    outResult->hit = false;
    outResult->normal = vec3(0, 0, 1);
    outResult->point = vec3(0, 0, 0);
}

void ResetCollisionManifold(CollisionManifold* result) {
    if (result == nullptr) return;
    result->colliding = false;
    result->normal = vec3(0, 0, 1);
    result->depth = FLT_MAX;
    result->contacts.clear();
}
