#include "Application/Render/FixedFunctionPhysics.h"

#include <glad/gl.h>

#include "Application/Render/FixedFunctionPrimitives.h"
#include "Physics/DistanceJoint.h"

// The book's Render() methods of the physics classes (docs/book-reference.md §3.2-3.8), drawn from read-only physics
// state.

namespace {

void SetRed() { SetLightColors(BookColors::kRigidbodyAmbient, BookColors::kRigidbodyDiffuse); }
void SetGround() { SetLightColors(BookColors::kGroundAmbient, BookColors::kGroundDiffuse); }
void SetGreen() { SetLightColors(BookColors::kConstraintAmbient, BookColors::kConstraintDiffuse); }

void Segment(const vec3& a, const vec3& b) {
    glVertex3f(a.x, a.y, a.z);
    glVertex3f(b.x, b.y, b.z);
}

/// The body's collision volumes as they are after SynchCollisionVolumes, built without mutating the body.
OBB BoxOf(const RigidbodyVolume& body) { return OBB(body.position, body.box.size, ToMat3(body.orientation)); }
Sphere SphereOf(const RigidbodyVolume& body) { return Sphere(body.position, body.sphere.radius); }

void SpringLines(const std::vector<Spring>& springs) {
    glBegin(GL_LINES);
    for (const Spring& s : springs)
        if (s.GetP1() != nullptr && s.GetP2() != nullptr) Segment(s.GetP1()->GetPosition(), s.GetP2()->GetPosition());
    glEnd();
}

/// Any body through the book's virtual Render().
void RenderBody(const Rigidbody& body) {
    switch (body.type) {
        case RigidbodyType::Particle:
            Render(static_cast<const Particle&>(body));
            break;
        case RigidbodyType::Sphere:
        case RigidbodyType::Box:
            Render(static_cast<const RigidbodyVolume&>(body));
            break;
        case RigidbodyType::Base:
            if (const auto* joint = dynamic_cast<const DistanceJoint*>(&body)) Render(*joint);
            break;
    }
}

}  // namespace

void Render(const Particle& particle) { Render(Sphere(particle.GetPosition(), 0.1f)); }

void Render(const RigidbodyVolume& body) {
    if (body.type == RigidbodyType::Sphere)
        Render(SphereOf(body));
    else if (body.type == RigidbodyType::Box)
        Render(BoxOf(body));
}

void Render(const DistanceJoint& joint) {
    if (joint.p1 == nullptr || joint.p2 == nullptr) return;
    glBegin(GL_LINES);
    Segment(joint.p1->GetPosition(), joint.p2->GetPosition());
    glEnd();
}

void Render(const Cloth& cloth, bool debug) {
    SetRed();
    if (debug) {
        for (const Particle& p : cloth.verts) Render(p);
        glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT);
        glDisable(GL_LIGHTING);
        glColor3f(1.0f, 0.0f, 1.0f);
        SpringLines(cloth.structural);
        glColor3f(1.0f, 1.0f, 0.0f);
        SpringLines(cloth.shear);
        glColor3f(0.0f, 1.0f, 1.0f);
        SpringLines(cloth.bend);
        glPopAttrib();
        return;
    }
    // Two one-sided triangles per cell, (tl, br, bl) and (tl, tr, br): front faces up for the flat cloth.
    const int n = cloth.GridSize();
    if (n < 2 || cloth.verts.size() < static_cast<std::size_t>(n) * static_cast<std::size_t>(n)) return;
    auto at = [&](int x, int z) { return cloth.verts[static_cast<std::size_t>(z * n + x)].GetPosition(); };
    for (int x = 0; x < n - 1; ++x)
        for (int z = 0; z < n - 1; ++z) {
            const vec3 tl = at(x, z), bl = at(x, z + 1), tr = at(x + 1, z), br = at(x + 1, z + 1);
            Render(Triangle(tl, br, bl), true);
            Render(Triangle(tl, tr, br), true);
        }
}

void Render(const PhysicsSystem& system) {
    if (system.DebugRender) glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);

    const std::vector<Rigidbody*>& bodies = system.Bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (system.RenderRandomColors) {
            const int c = static_cast<int>(i % 3);
            if (c == 0)
                SetRed();
            else if (c == 1)
                SetGround();
            else
                SetGreen();
        } else {
            SetRed();
        }
        const Rigidbody& body = *bodies[i];
        if (system.DebugRender && body.type == RigidbodyType::Box)
            Render(GetEdges(BoxOf(static_cast<const RigidbodyVolume&>(body))));
        else
            RenderBody(body);
    }

    const std::vector<OBB>& constraints = system.Constraints();
    for (std::size_t i = 0; i < constraints.size(); ++i) {
        if (i == 0)
            SetGround();
        else
            SetGreen();
        Render(constraints[i]);
    }

    if (system.DebugRender) {
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        glPushAttrib(GL_ENABLE_BIT);
        glDisable(GL_LIGHTING);
        const std::vector<CollisionPair>& pairs = system.Collisions();
        for (std::size_t i = 0; i < system.CollisionCount() && i < pairs.size(); ++i) Render(pairs[i].manifold);
        glPopAttrib();
    }

    // Spring lines, lit, each drawn once (erratum 5.2-19: the book's nested loop drew each N times).
    SpringLines(system.Springs());

    for (const Cloth* cloth : system.Cloths()) Render(*cloth, system.DebugRender);
}
