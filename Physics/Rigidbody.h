#pragma once
// Base of every simulated object (docs/book-reference.md §3.1). The book's type ids are kept as the enum's values.
// Physics never draws: demos hand its state to the rendering layer.

#include <vector>

#include "Physics/Geometry/Geometry3D.h"

enum class RigidbodyType { Base = 0, Particle = 1, Sphere = 2, Box = 3 };

class Rigidbody {
public:
    RigidbodyType type = RigidbodyType::Base;

    Rigidbody() = default;
    explicit Rigidbody(RigidbodyType t) : type(t) {}
    virtual ~Rigidbody() = default;

    virtual void Update(float /*dt*/) {}
    virtual void ApplyForces() {}
    virtual void SolveConstraints(const std::vector<OBB>& /*constraints*/) {}

    /// True for spheres and boxes: only these take part in pair collision tests.
    bool HasVolume() const { return type == RigidbodyType::Sphere || type == RigidbodyType::Box; }
};
