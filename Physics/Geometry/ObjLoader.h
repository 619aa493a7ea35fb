#pragma once
// OBJ models through tinyobjloader into a Mesh.

#include <string>

#include "Physics/Geometry/Geometry3D.h"

/// Loads every face of `path` (triangulated) into out->triangles and builds the BVH.
/// Returns false with *error naming the file and the problem (missing, unreadable, malformed, no faces).
bool LoadMesh(const std::string& path, Mesh* out, std::string* error);
