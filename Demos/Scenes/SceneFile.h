#pragma once
// Scene files (docs/scenes.md): a JSON file read into a plain SceneDescription, validated at the boundary. Every
// problem is reported as "FILE: PATH: message (value)" with a JSON path such as bodies[3].mass; syntax errors and
// a key given twice in one object carry the line and column. Unknown keys are errors, so typos are caught. GL-free.

#include <cstddef>
#include <string>
#include <vector>

#include "Demos/Scenes/ModelRequest.h"
#include "Math/quaternion.h"
#include "Math/vectors.h"
#include "Physics/ContactSolver.h"
#include "Physics/Integrator.h"
#include "Physics/Particle.h"
#include "Physics/WorldSettings.h"

/// Documented limits of one scene file (docs/scenes.md, "Limits"); larger files or counts are errors.
struct SceneLimits {
    static constexpr std::size_t kMaxFileBytes = 4u << 20;  ///< bytes
    /// Levels of arrays and objects inside each other (a scene needs 4: bodies[i].position[k]).
    static constexpr std::size_t kMaxNesting = 64;
    static constexpr std::size_t kMaxBodies = 10000;
    static constexpr std::size_t kMaxConstraints = 1000;
    static constexpr std::size_t kMaxSprings = 50000;
    static constexpr std::size_t kMaxJoints = 10000;
    static constexpr std::size_t kMaxCloths = 16;
    static constexpr int kMaxClothGrid = 100;       ///< particles per side
    static constexpr int kMaxIterations = 1000;     ///< solver passes
    static constexpr int kMaxSubsteps = 1024;       ///< volume substeps
    static constexpr float kMinDuration = 0.001f;   ///< s
    static constexpr float kMaxDuration = 3600.0f;  ///< s
    /// kg, a body's mass other than 0 (static) and a cloth particle's: 1/m and m g stay finite floats.
    static constexpr float kMinMass = 1e-6f;
    static constexpr float kMaxMass = 1e9f;
    /// s, world.step other than 0 (the host's): --dt's range (docs/app.md, "Steps").
    static constexpr float kMinStep = 0.0001f;
    static constexpr float kMaxStep = 1.0f;
};

/// The format version this build reads.
constexpr int kSceneFormatVersion = 1;

/// World settings of a scene; every field defaults to the engine's default (WorldSettings.h).
struct SceneWorld {
    vec3 gravity{0.0f, -9.82f, 0.0f};  ///< m/s^2, applied to every body and cloth particle
    float step = 0.0f;                 ///< s, the physics step; 0 = the host's (--dt, book 0.03)
    Integrator integrator = Integrator::SemiImplicitEuler;
    ParticleContact particleContact = ParticleContact::Book;  ///< how particles meet boxes (Physics/Particle.h)
    JointModel jointModel = JointModel::Book;  ///< how distance joints hold their particles (Physics/JointModel.h)
    ContactSolver contactSolver = ContactSolver::Book;
    VolumePositions volumePositions = VolumePositions::Euler;  ///< volumes' position update (VolumePositions.h)
    int iterations = 5;                                        ///< solver passes per (sub)step
    float penetrationSlop = 0.01f;                             ///< m
    bool linearProjection = true;
    float projectionFraction = 0.45f;   ///< 0..1
    int maxSubsteps = 64;               ///< volume substeps per step, 1 = off
    float warmStartFactor = 1.0f;       ///< accumulated solver, 0..1
    float baumgarte = 0.0f;             ///< accumulated solver, 0..1
    float restitutionThreshold = 1.0f;  ///< accumulated solver, m/s
    SoftSolverSettings soft;            ///< world.soft: the soft solver's settings (units in ContactSolver.h)
    SleepSettings sleep;                ///< world.sleep: islands and sleep (units in WorldSettings.h), off
};

/// The book's orbit camera (docs/book-reference.md §1.4).
struct SceneCamera {
    vec3 target{3.75622f, 2.98255f, 0.0f};  ///< world, m
    vec2 rotation{-67.9312f, 19.8f};        ///< yaw, pitch, degrees
    float zoom = 9.0f;                      ///< distance from the target, m
};

enum class SceneBodyKind { Particle, Sphere, Box };

/// One body. Defaults are the engine's: volumes friction 0.6, restitution 0.5, retention 0.98 per 0.03 s;
/// particles restitution (the book's bounce) 0.7, retention 0.95 per 0.03 s.
struct SceneBody {
    std::string id;
    SceneBodyKind kind = SceneBodyKind::Box;
    vec3 position;                       ///< world, m
    vec3 halfExtents{1.0f, 1.0f, 1.0f};  ///< m, boxes only
    float radius = 1.0f;                 ///< m, spheres only
    vec3 eulerDegrees;                   ///< the book's (pitch, yaw, roll), degrees; volumes only
    bool hasQuaternion = false;          ///< orientation given as a quaternion instead
    quat orientation;                    ///< normalised; volumes only
    vec3 velocity;                       ///< m/s
    vec3 angularVelocity;                ///< rad/s, world; volumes only
    float mass = 1.0f;                   ///< kg, 0 = static
    float restitution = 0.5f;
    float friction = 0.6f;            ///< volumes only
    float velocityRetention = 0.98f;  ///< fraction kept per 0.03 s
    /// m/s and rad/s per 0.03 s: velocity components below this are zeroed (RigidbodyVolume::velocityEpsilon);
    /// volumes only, 0 = none.
    float velocityEpsilon = 0.001f;
    bool hasColor = false;
    vec3 color;  ///< RGB 0..1
};

/// A static OBB (the book's constraints, which particles bounce off).
struct SceneConstraint {
    vec3 position;                       ///< world, m
    vec3 halfExtents{1.0f, 1.0f, 1.0f};  ///< m
    vec3 eulerDegrees;                   ///< the book's (pitch, yaw, roll), degrees
};

/// A damped spring between two particles (Spring.h): force constants in N/m and N s/m.
struct SceneSpring {
    std::size_t a = 0, b = 0;  ///< indices into SceneDescription::bodies (particles)
    float stiffness = 1.0f;    ///< N/m, > 0 pulls the ends towards the rest length
    float damping = 0.0f;      ///< N s/m
    float restLength = 1.0f;   ///< m
};

/// A rigid distance between two particles (DistanceJoint.h).
struct SceneJoint {
    std::size_t a = 0, b = 0;  ///< indices into SceneDescription::bodies (particles)
    float length = 1.0f;       ///< m
};

/// The book's cloth grid (Cloth.h): gridSize x gridSize particles `spacing` apart in the x-z plane from position.
struct SceneCloth {
    int gridSize = 15;
    float spacing = 0.4f;                                              ///< m
    vec3 position;                                                     ///< world, m: the grid's centre
    float particleMass = 1.0f;                                         ///< kg
    float velocityRetention = 0.9f;                                    ///< per 0.03 s; the book's cloth (Cloth.cpp)
    float structuralStiffness = 166.66667f, structuralDamping = 0.0f;  ///< N/m, N s/m
    float shearStiffness = 166.66667f, shearDamping = 0.0f;
    float bendStiffness = 166.66667f, bendDamping = 0.0f;
};

/// Everything a scene file names, validated.
struct SceneDescription {
    int format = kSceneFormatVersion;
    std::string name;
    float duration = 10.0f;  ///< s, the run length when --frames is not given
    /// "model" and "budget" (docs/scenes.md, "Error budget"): fixed (the world's own settings) unless "auto"; a
    /// budget without "auto" is kept for `--set model=auto`.
    AutoModelRequest autoModel;
    SceneWorld world;
    SceneCamera camera;
    std::vector<SceneBody> bodies;
    std::vector<SceneConstraint> constraints;
    std::vector<SceneSpring> springs;
    std::vector<SceneJoint> joints;
    std::vector<SceneCloth> cloths;
};

/// Parses `text` (the contents of `fileName`, used in messages only) into *out. Returns false and appends one
/// "FILE: PATH: message" line per problem to *errors (then *out is unspecified). A value adjusted rather than
/// refused (world.step rounded to whole microseconds) appends a "FILE: PATH: note" line to *notes, if given.
bool ParseSceneText(const std::string& text, const std::string& fileName, SceneDescription* out,
                    std::vector<std::string>* errors, std::vector<std::string>* notes = nullptr);
/// Reads `fileName` (a regular file of at most SceneLimits::kMaxFileBytes) and parses it as ParseSceneText.
bool LoadSceneFile(const std::string& fileName, SceneDescription* out, std::vector<std::string>* errors,
                   std::vector<std::string>* notes = nullptr);
/// 1-based line and column of the byte at 0-based `offset` in `text` (clamped to its end).
void LineAndColumn(const std::string& text, std::size_t offset, int* line, int* column);
