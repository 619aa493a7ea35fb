#include "Demos/Scenes/SceneExport.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <nlohmann/json.hpp>

#include "Math/matrices.h"
#include "Physics/Cloth.h"
#include "Physics/DistanceJoint.h"
#include "Physics/ModelChoice/ModelChoice.h"
#include "Physics/Particle.h"
#include "Physics/RigidbodyVolume.h"
#include "Physics/Spring.h"

using Json = nlohmann::json;

namespace {

/// The float as the double with the fewest decimal digits that reads back as the same float (so the JSON shows
/// 0.3, not 0.30000001192092896).
double Shortest(float v) {
    char text[32];
    for (int precision = 1; precision <= 9; ++precision) {
        std::snprintf(text, sizeof text, "%.*g", precision, static_cast<double>(v));
        if (std::strtof(text, nullptr) == v) break;
    }
    return std::strtod(text, nullptr);
}
Json J(float v) { return Shortest(v); }
Json J(const vec3& v) { return Json::array({Shortest(v.x), Shortest(v.y), Shortest(v.z)}); }

/// world.soft: the soft solver's fields that differ from their defaults (an empty object when none does).
Json SoftObject(const SoftSolverSettings& soft) {
    const SoftSolverSettings d;
    Json o = Json::object();
    if (soft.substeps != d.substeps) o["substeps"] = soft.substeps;
    if (soft.iterations != d.iterations) o["iterations"] = soft.iterations;
    if (soft.relaxIterations != d.relaxIterations) o["relaxIterations"] = soft.relaxIterations;
    const struct {
        const char* key;
        float value, defaultValue;
    } numbers[] = {{"contactHertz", soft.contactHertz, d.contactHertz},
                   {"contactDampingRatio", soft.contactDampingRatio, d.contactDampingRatio},
                   {"maxPushoutSpeed", soft.maxPushoutSpeed, d.maxPushoutSpeed},
                   {"speculativeMargin", soft.speculativeMargin, d.speculativeMargin},
                   {"linearSlop", soft.linearSlop, d.linearSlop},
                   {"restitutionThreshold", soft.restitutionThreshold, d.restitutionThreshold},
                   {"warmStartFactor", soft.warmStartFactor, d.warmStartFactor}};
    for (const auto& n : numbers)
        if (n.value != n.defaultValue) o[n.key] = J(n.value);
    return o;
}

/// world.sleep: nothing (null) at the defaults, true when only `enabled` differs, else the whole object.
Json SleepValue(const SleepSettings& sleep) {
    const SleepSettings d;
    const bool sameThresholds = sleep.timeToSleep == d.timeToSleep && sleep.linearSpeed == d.linearSpeed &&
                                sleep.angularSpeed == d.angularSpeed;
    if (sameThresholds) return sleep.enabled == d.enabled ? Json() : Json(sleep.enabled);
    return {{"enabled", sleep.enabled},
            {"timeToSleep", J(sleep.timeToSleep)},
            {"linearSpeed", J(sleep.linearSpeed)},
            {"angularSpeed", J(sleep.angularSpeed)}};
}

bool SameMatrix(const mat3& a, const mat3& b) {
    for (int i = 0; i < 9; ++i) {
        if (a.asArray[i] != b.asArray[i]) return false;
    }
    return true;
}

/// What DescribeWorld builds, piece by piece: the description, its notes, the one world gravity and the particles'
/// indices (for the springs' and joints' ends).
struct Describer {
    SceneDescription d;
    std::vector<std::string>* notes;
    bool haveGravity = false;
    std::map<const Particle*, std::size_t> particleIds;

    void Settings(const WorldSettings& s) {
        d.world.integrator = s.integrator;
        d.world.particleContact = s.particleContact;
        d.world.jointModel = s.jointModel;
        d.world.contactSolver = s.contactSolver;
        d.world.volumePositions = s.volumePositions;
        d.world.iterations = s.solverIterations;
        d.world.penetrationSlop = s.penetrationSlop;
        d.world.linearProjection = s.linearProjection;
        d.world.projectionFraction = s.projectionFraction;
        d.world.maxSubsteps = s.maxVolumeSubsteps;
        d.world.warmStartFactor = s.accumulated.warmStartFactor;
        d.world.baumgarte = s.accumulated.baumgarte;
        d.world.restitutionThreshold = s.accumulated.restitutionThreshold;
        d.world.soft = s.soft;
        d.world.sleep = s.sleep;
    }
    void Gravity(const vec3& g, const std::string& what) {
        if (!haveGravity) {
            d.world.gravity = g;
            haveGravity = true;
        } else if (g.x != d.world.gravity.x || g.y != d.world.gravity.y || g.z != d.world.gravity.z) {
            notes->push_back(what + ": its own gravity is not expressible (the file has one world gravity)");
        }
    }
    void ParticleBody(const Particle& p, const std::string& what, SceneBody* b) {
        b->kind = SceneBodyKind::Particle;
        b->position = p.GetPosition();
        b->velocity = p.GetVelocity();
        b->mass = p.GetMass();
        b->restitution = p.GetBounce();
        b->velocityRetention = p.GetVelocityRetention();
        if (p.GetOldPosition().x != b->position.x || p.GetOldPosition().y != b->position.y ||
            p.GetOldPosition().z != b->position.z) {
            notes->push_back(what + ": its previous position (Verlet state) is not expressible");
        }
        Gravity(p.GetGravity(), what);
        particleIds[&p] = d.bodies.size();
    }
    void VolumeBody(const RigidbodyVolume& v, const std::string& what, SceneBody* b) {
        b->kind = v.type == RigidbodyType::Sphere ? SceneBodyKind::Sphere : SceneBodyKind::Box;
        b->position = v.position;
        b->halfExtents = v.box.size;
        b->radius = v.sphere.radius;
        b->hasQuaternion = true;
        b->orientation = v.orientation;
        b->velocity = v.velocity;
        b->angularVelocity = v.angVel;
        b->mass = v.mass;
        b->restitution = v.cor;
        b->friction = v.friction;
        b->velocityRetention = v.velocityRetention;
        b->velocityEpsilon = v.velocityEpsilon;
        Gravity(v.gravity, what);
    }
    void Bodies(const PhysicsSystem& system) {
        for (const Rigidbody* body : system.Bodies()) {
            SceneBody b;
            b.id = "b" + std::to_string(d.bodies.size());
            const std::string what = "body " + b.id;
            if (body->type == RigidbodyType::Particle) {
                ParticleBody(static_cast<const Particle&>(*body), what, &b);
            } else if (body->type == RigidbodyType::Sphere || body->type == RigidbodyType::Box) {
                VolumeBody(static_cast<const RigidbodyVolume&>(*body), what, &b);
            } else {
                continue;  // joints below; other kinds have no place in the format
            }
            d.bodies.push_back(b);
        }
    }
    void Constraints(const PhysicsSystem& system) {
        for (std::size_t i = 0; i < system.Constraints().size(); ++i) {
            const OBB& obb = system.Constraints()[i];
            SceneConstraint c;
            c.position = obb.position;
            c.halfExtents = obb.size;
            c.eulerDegrees = Decompose(obb.orientation);
            const vec3& e = c.eulerDegrees;
            if (!SameMatrix(Rotation3x3(e.x, e.y, e.z), obb.orientation)) {
                notes->push_back("constraints[" + std::to_string(i) +
                                 "]: orientation written as Euler degrees that rebuild it only approximately");
            }
            d.constraints.push_back(c);
        }
    }
    bool IdOf(const Particle* p, std::size_t* out) const {
        auto it = particleIds.find(p);
        if (it == particleIds.end()) return false;
        *out = it->second;
        return true;
    }
    void Links(const PhysicsSystem& system) {
        for (std::size_t i = 0; i < system.Springs().size(); ++i) {
            const Spring& spring = system.Springs()[i];
            SceneSpring s2;
            if (!IdOf(spring.GetP1(), &s2.a) || !IdOf(spring.GetP2(), &s2.b)) {
                notes->push_back("spring " + std::to_string(i) + ": an end is not a free particle; left out");
                continue;
            }
            s2.stiffness = -spring.k;
            s2.damping = spring.b;
            s2.restLength = spring.restingLength;
            d.springs.push_back(s2);
        }
        for (std::size_t i = 0; i < system.Joints().size(); ++i) {
            const DistanceJoint& joint = *system.Joints()[i];
            SceneJoint j;
            if (!IdOf(joint.p1, &j.a) || !IdOf(joint.p2, &j.b)) {
                notes->push_back("joint " + std::to_string(i) + ": an end is not a free particle; left out");
                continue;
            }
            j.length = joint.length;
            d.joints.push_back(j);
        }
    }
    void Cloths(const PhysicsSystem& system) {
        for (std::size_t i = 0; i < system.Cloths().size(); ++i) {
            const Cloth& cloth = *system.Cloths()[i];
            const std::vector<Particle>& v = cloth.verts;
            SceneCloth c;
            c.gridSize = cloth.GridSize();
            c.spacing = v[1].GetPosition().x - v[0].GetPosition().x;
            c.position = (v.front().GetPosition() + v.back().GetPosition()) * 0.5f;
            c.particleMass = v[0].GetMass();
            c.velocityRetention = v[0].GetVelocityRetention();
            if (!cloth.structural.empty())
                c.structuralStiffness = -cloth.structural[0].k, c.structuralDamping = cloth.structural[0].b;
            if (!cloth.shear.empty()) c.shearStiffness = -cloth.shear[0].k, c.shearDamping = cloth.shear[0].b;
            if (!cloth.bend.empty()) c.bendStiffness = -cloth.bend[0].k, c.bendDamping = cloth.bend[0].b;
            if (!RebuildingSpacing(v, &c))
                notes->push_back("cloth " + std::to_string(i) + ": not the book's flat grid; written as one");
            Gravity(v[0].GetGravity(), "cloth " + std::to_string(i));
            d.cloths.push_back(c);
        }
    }
    /// The spacing read from the positions may be a float or two off the one the grid was built with: the
    /// nearest that rebuilds every particle exactly is taken (into c->spacing). False when none within 64 floats
    /// of it does.
    static bool RebuildingSpacing(const std::vector<Particle>& v, SceneCloth* c) {
        float down = c->spacing, up = c->spacing;
        for (int k = 0; k < 64; ++k) {
            for (float spacing : {down, up}) {
                Cloth rebuilt;
                rebuilt.Initialize(c->gridSize, spacing, c->position);
                bool match = rebuilt.verts.size() == v.size();
                for (std::size_t m = 0; match && m < v.size(); ++m) {
                    const vec3 p = rebuilt.verts[m].GetPosition(), q = v[m].GetPosition();
                    match = p.x == q.x && p.y == q.y && p.z == q.z;
                }
                if (match) {
                    c->spacing = spacing;
                    return true;
                }
            }
            down = std::nextafter(down, 0.0f);
            up = std::nextafter(up, 1e9f);
        }
        return false;
    }
};

}  // namespace

SceneDescription DescribeWorld(const PhysicsSystem& system, const std::string& name, std::vector<std::string>* notes) {
    Describer describer;
    describer.notes = notes;
    describer.d.name = name;
    describer.Settings(system.settings);
    describer.Bodies(system);
    describer.Constraints(system);
    describer.Links(system);
    describer.Cloths(system);
    return describer.d;
}

namespace {

/// The scene file's "world" object.
Json WorldJson(const SceneWorld& w) {
    Json world = {{"gravity", J(w.gravity)},
                  {"integrator", ToString(w.integrator)},
                  {"contactSolver", ToString(w.contactSolver)},
                  {"iterations", w.iterations},
                  {"penetrationSlop", J(w.penetrationSlop)},
                  {"linearProjection", w.linearProjection},
                  {"projectionFraction", J(w.projectionFraction)},
                  {"substeps", w.maxSubsteps},
                  {"warmStartFactor", J(w.warmStartFactor)},
                  {"baumgarte", J(w.baumgarte)},
                  {"restitutionThreshold", J(w.restitutionThreshold)}};
    // Only a non-book contact is written, so exports of the book's scenes stay as they were.
    if (w.particleContact != ParticleContact::Book) world["particleContact"] = ToString(w.particleContact);
    if (w.jointModel != JointModel::Book) world["jointModel"] = ToString(w.jointModel);
    if (w.volumePositions != VolumePositions::Euler) world["volumePositions"] = ToString(w.volumePositions);
    if (w.step > 0.0f) world["step"] = J(w.step);
    // Written only where they differ from the defaults (docs/scenes.md, "Export").
    if (const Json soft = SoftObject(w.soft); !soft.empty()) world["soft"] = soft;
    if (const Json sleep = SleepValue(w.sleep); !sleep.is_null()) world["sleep"] = sleep;
    return world;
}

/// One body's object in the scene file's "bodies" list.
Json BodyJson(const SceneBody& b) {
    Json o = {{"id", b.id}, {"position", J(b.position)}};
    o["velocity"] = J(b.velocity);
    o["mass"] = J(b.mass);
    o["restitution"] = J(b.restitution);
    o["velocityRetention"] = J(b.velocityRetention);
    if (b.kind == SceneBodyKind::Particle) {
        o["type"] = "particle";
    } else {
        o["type"] = b.kind == SceneBodyKind::Sphere ? "sphere" : "box";
        if (b.kind == SceneBodyKind::Sphere) {
            o["radius"] = J(b.radius);
        } else {
            o["halfExtents"] = J(b.halfExtents);
        }
        if (b.hasQuaternion) {
            const quat& q = b.orientation;
            o["quaternion"] = Json::array({Shortest(q.x), Shortest(q.y), Shortest(q.z), Shortest(q.w)});
        } else {
            o["euler"] = J(b.eulerDegrees);
        }
        o["angularVelocity"] = J(b.angularVelocity);
        o["friction"] = J(b.friction);
        // Only where it differs from the engine's default, so the shipped exports keep their text.
        if (b.velocityEpsilon != SceneBody().velocityEpsilon) o["velocityEpsilon"] = J(b.velocityEpsilon);
    }
    if (b.hasColor) o["color"] = J(b.color);
    return o;
}

/// One cloth's object in the scene file's "cloths" list.
Json ClothJson(const SceneCloth& c) {
    return {{"gridSize", c.gridSize},
            {"spacing", J(c.spacing)},
            {"position", J(c.position)},
            {"particleMass", J(c.particleMass)},
            {"velocityRetention", J(c.velocityRetention)},
            {"structural", {{"stiffness", J(c.structuralStiffness)}, {"damping", J(c.structuralDamping)}}},
            {"shear", {{"stiffness", J(c.shearStiffness)}, {"damping", J(c.shearDamping)}}},
            {"bend", {{"stiffness", J(c.bendStiffness)}, {"damping", J(c.bendDamping)}}}};
}

}  // namespace

std::string WriteSceneText(const SceneDescription& d) {
    Json root = Json::object();
    root["format"] = d.format;
    root["name"] = d.name;
    root["duration"] = J(d.duration);
    if (d.autoModel.Auto()) {  // a fixed model writes neither key, so exports without auto stay as they were
        root["model"] = "auto";
        root["budget"] = {{"quantity", ToString(static_cast<BudgetQuantity>(d.autoModel.quantity))},
                          {"bound", J(d.autoModel.bound)}};
    }
    root["world"] = WorldJson(d.world);
    root["camera"] = {{"target", J(d.camera.target)},
                      {"rotation", Json::array({Shortest(d.camera.rotation.x), Shortest(d.camera.rotation.y)})},
                      {"zoom", J(d.camera.zoom)}};
    Json bodies = Json::array();
    for (const SceneBody& b : d.bodies) bodies.push_back(BodyJson(b));
    root["bodies"] = bodies;
    Json constraints = Json::array();
    for (const SceneConstraint& c : d.constraints) {
        constraints.push_back(
            {{"position", J(c.position)}, {"halfExtents", J(c.halfExtents)}, {"euler", J(c.eulerDegrees)}});
    }
    root["constraints"] = constraints;
    Json springs = Json::array();
    for (const SceneSpring& s : d.springs) {
        springs.push_back({{"a", d.bodies[s.a].id},
                           {"b", d.bodies[s.b].id},
                           {"stiffness", J(s.stiffness)},
                           {"damping", J(s.damping)},
                           {"restLength", J(s.restLength)}});
    }
    root["springs"] = springs;
    Json joints = Json::array();
    for (const SceneJoint& j : d.joints) {
        joints.push_back({{"a", d.bodies[j.a].id}, {"b", d.bodies[j.b].id}, {"length", J(j.length)}});
    }
    root["joints"] = joints;
    Json cloths = Json::array();
    for (const SceneCloth& c : d.cloths) cloths.push_back(ClothJson(c));
    root["cloths"] = cloths;
    return root.dump(2) + "\n";
}
