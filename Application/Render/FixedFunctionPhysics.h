#pragma once
// Drawing of physics state (the book's PhysicsSystem::Render, Particle::Render, Cloth::Render ...), moved
// out of Physics/ so that physics never includes GL. Colour table of docs/book-reference.md §1.5.

#include "Physics/Cloth.h"
#include "Physics/DistanceJoint.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"

/// Book colours (docs/book-reference.md §1.5), as light ambient/diffuse.
namespace BookColors {
constexpr vec3 kRigidbodyDiffuse{200.0f / 255.0f, 0.0f, 0.0f};
constexpr vec3 kRigidbodyAmbient{200.0f / 255.0f, 50.0f / 255.0f, 50.0f / 255.0f};
constexpr vec3 kGroundDiffuse{0.0f, 0.0f, 200.0f / 255.0f};
constexpr vec3 kGroundAmbient{50.0f / 255.0f, 50.0f / 255.0f, 200.0f / 255.0f};
constexpr vec3 kConstraintDiffuse{0.0f, 200.0f / 255.0f, 0.0f};
constexpr vec3 kConstraintAmbient{50.0f / 255.0f, 200.0f / 255.0f, 50.0f / 255.0f};
}  // namespace BookColors

/// A sphere of radius 0.1 at the particle, in the current light colours (PhysicsSystem sets red).
void Render(const Particle& particle);
/// Sphere or box of the body at its current position and orientation (as after SynchCollisionVolumes),
/// in the current light colours.
void Render(const RigidbodyVolume& body);
/// A line between the joint's two particles (lit, as in the book); nothing if a particle is missing.
void Render(const DistanceJoint& joint);
/// debug: particles and magenta/yellow/cyan spring lines; otherwise red one-sided triangles.
void Render(const Cloth& cloth, bool debug);
/// The book's PhysicsSystem::Render (docs/book-reference.md §3.4): bodies (random colours if RenderRandomColors),
/// constraint 0 blue and the rest green, manifolds if DebugRender, spring lines, cloths.
void Render(const PhysicsSystem& system);
