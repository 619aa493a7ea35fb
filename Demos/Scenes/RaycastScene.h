#pragma once
// Raycast Demo scene (docs/book-reference.md §2.0): five primitives, plus an OBJ mesh model raycast through its BVH,
// and the scripted cursor that stands in for the mouse in headless runs. GL-free; shared by RaycastDemo and tests.

#include <string>

#include "Demos/Scenes/Parameters.h"
#include "Physics/Geometry/Geometry3D.h"

/// The demo's script values (the book has no panel here); ranges and labels are in AddRaycastParameters.
struct RaycastParams {
    bool script = true;  ///< sweep a pick ray across the screen (false: the book's state before any click)
    float speed = 1.0f;  ///< sweeps per kSweepFrames output frames
};

/// Registers script (checkbox "Scripted pick") and speed (100 px slider "Speed") bound to *params on *set.
void AddRaycastParameters(ParameterSet* set, RaycastParams* params);

class RaycastScene {
public:
    /// Output frames for one full sweep at speed 1 (left to right along the upper row, back along the lower).
    static constexpr int kSweepFrames = 240;
    /// Which shape a pick hit.
    enum class Shape { None = -1, Sphere, AABB, OBB, Plane, Triangle, Model };

    Sphere sphere{{-4.0f, 2.0f, 0.0f}, 1.0f};
    AABB aabb{{4.0f, 2.0f, 0.0f}, {1.0f, 1.0f, 1.0f}};
    OBB obb;            ///< (-4, -2, 0), unit half-size, Rotation3x3(30, 20, 0)
    Plane plane;        ///< FromTriangle((4,-1,0), (3,-3,0), (3,-3,1))
    Triangle triangle;  ///< (0,3,0), (-1,1,0), (1,1,0): normal +Z, one-sided for rays from the default camera
    Mesh mesh;
    Model model;  ///< the mesh, at kModelPosition; content null until LoadModel succeeds

    /// Where the model sits: the free slot below the triangle, between the OBB and the plane.
    static constexpr vec3 kModelPosition{0.0f, -2.0f, 0.0f};

    RaycastScene();
    RaycastScene(const RaycastScene&) = delete;
    RaycastScene& operator=(const RaycastScene&) = delete;

    /// Loads the OBJ into `mesh` (with its BVH) and points the model at it. On failure the model stays empty
    /// and *error says why.
    bool LoadModel(const std::string& path, std::string* error);
    bool HasModel() const { return model.content != nullptr; }

    /// Closest hit (smallest t) over the five primitives and the model; *shape says which (None on a miss).
    RaycastResult CastAll(const Ray& ray, Shape* shape) const;

    /// Scripted cursor in pixels (top-left origin) for output frame `frame`: a boustrophedon sweep between
    /// 10 % and 90 % of the width, along the row of the upper shapes (y = 2) then back along the lower row
    /// (y = -2) as seen from the default camera.
    static vec2 ScriptedCursor(int frame, float speed, const vec2& viewportSize);
};

/// The first *.obj file (by name) in `directory`, or "" if there is none.
std::string FirstObjFile(const std::string& directory);
