#pragma once
// A world written as a scene file (docs/scenes.md, "Export"): `physics-sandbox --demo ID --export-scene FILE`.
// GL-free. What the format cannot express is listed, not silently dropped.

#include <string>
#include <vector>

#include "Demos/Scenes/SceneFile.h"
#include "Physics/PhysicsSystem.h"

/// Describes `system` as a scene named `name`: its settings, bodies (particles, spheres, boxes, in insertion order),
/// constraints, springs, joints and cloths. Appends to *notes one line per thing the format cannot express exactly
/// (a constraint's orientation that is not the book's Euler rotation, a body whose gravity differs from the
/// first one's, a cloth that is not the book's square grid).
SceneDescription DescribeWorld(const PhysicsSystem& system, const std::string& name, std::vector<std::string>* notes);
/// The description as scene-file text (JSON, two-space indent). Every number is written with the fewest digits
/// that read back as the same float, so ParseSceneText gives the same description.
std::string WriteSceneText(const SceneDescription& description);
