#include "Demos/Scenes/SceneFile.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <utility>

#include "Demos/Scenes/ContactSolverParameters.h"
#include "Demos/Scenes/DuplicateKeys.h"
#include "Demos/Scenes/JsonNesting.h"
#include "Demos/Scenes/StepValue.h"
#include "Physics/ModelChoice/ModelChoice.h"

using Json = nlohmann::json;

namespace {

/// Value ranges a number may be restricted to (docs/scenes.md lists each field's).
enum class Range { Any, NonNegative, Positive, Fraction };

/// Collects "FILE: PATH: message (value)" lines.
class Problems {
public:
    Problems(std::string fileName, std::vector<std::string>* out, std::vector<std::string>* notesOut = nullptr)
        : file(std::move(fileName)), lines(out), notes(notesOut) {}
    /// A "FILE: PATH: message" note about a value that was adjusted, not refused (a step rounded to microseconds).
    void Note(const std::string& path, const std::string& message) {
        if (notes != nullptr) notes->push_back(file + ": " + path + ": " + message);
    }
    void Add(const std::string& path, const std::string& message, const Json* value = nullptr) {
        std::string line = file + ": " + (path.empty() ? std::string("(top level)") : path) + ": " + message;
        if (value != nullptr) {
            std::string text = value->dump();
            if (text.size() > 60) text = text.substr(0, 57) + "...";
            line += " (got " + text + ")";
        }
        lines->push_back(line);
        ++count;
    }
    int Count() const { return count; }

private:
    std::string file;
    std::vector<std::string>* lines;
    std::vector<std::string>* notes;
    int count = 0;
};

/// A bound as the shortest decimal that names it ("0.1", "1000").
std::string Decimal(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", static_cast<double>(v));
    return text;
}

/// The engine stores every number as a float: one beyond its range, or non-zero but below its smallest normal
/// magnitude (5e-324 or 1e-45 would become 0 or a denormal whose inverse is infinite), is refused with the range.
const char* const kFiniteMessage = "must be finite (a float: magnitude at most 3.40282e+38)";
const char* const kUnderflowMessage = "is too small for a float: must be 0 or of magnitude at least 1.17549e-38";
bool BelowFloat(double d) { return d != 0.0 && std::fabs(d) < static_cast<double>(FLT_MIN); }

std::string Join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }
std::string Index(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

/// Reads the fields of one JSON object, remembering which keys were read so Finish can reject the rest.
class ObjectReader {
public:
    ObjectReader(const Json& object, std::string objectPath, Problems* problems)
        : obj(object), path(std::move(objectPath)), out(problems) {
        ok = obj.is_object();
        if (!ok) out->Add(path, "must be an object", &obj);
    }
    bool Valid() const { return ok; }
    bool Has(const char* key) const { return ok && obj.contains(key); }

    /// A number into *value; range-checked after conversion to float (so 1e39 is reported as infinite).
    void Float(const char* key, float* value, Range range, bool required = false) {
        const Json* v = Find(key, required);
        if (v == nullptr) return;
        if (!v->is_number()) return Bad(key, "must be a number", v);
        const double d = v->get<double>();
        const float f = static_cast<float>(d);
        if (!std::isfinite(d) || !std::isfinite(f)) return Bad(key, kFiniteMessage, v);
        if (BelowFloat(d)) return Bad(key, kUnderflowMessage, v);
        if (range == Range::NonNegative && f < 0.0f) return Bad(key, "must be >= 0", v);
        if (range == Range::Positive && !(f > 0.0f)) return Bad(key, "must be > 0", v);
        if (range == Range::Fraction && !(f >= 0.0f && f <= 1.0f)) return Bad(key, "must be in [0, 1]", v);
        *value = f;
    }
    /// A number into *value, in [lo, hi] (inclusive, compared as the float that is stored); with zeroToo, 0 is
    /// also accepted ("must be 0 or in [lo, hi]"). A number too small for a float is out of the range.
    void FloatIn(const char* key, float* value, float lo, float hi, bool zeroToo = false) {
        const Json* v = Find(key, false);
        if (v == nullptr) return;
        if (!v->is_number()) return Bad(key, "must be a number", v);
        const double d = v->get<double>();
        const float f = static_cast<float>(d);
        if (!std::isfinite(d) || !std::isfinite(f)) return Bad(key, kFiniteMessage, v);
        const bool zero = d == 0.0;
        if ((zero && !zeroToo && !(lo <= 0.0f)) || (!zero && (BelowFloat(d) || !(f >= lo && f <= hi)))) {
            const std::string range = "[" + Decimal(lo) + ", " + Decimal(hi) + "]";
            return Bad(key, zeroToo ? "must be 0 or in " + range : "must be in " + range, v);
        }
        *value = f;
    }
    void Int(const char* key, int* value, int lo, int hi, bool required = false) {
        const Json* v = Find(key, required);
        if (v == nullptr) return;
        if (!v->is_number_integer()) return Bad(key, "must be an integer", v);
        const long long n = v->get<long long>();
        if (n < lo || n > hi) {
            return Bad(key, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]", v);
        }
        *value = static_cast<int>(n);
    }
    void Bool(const char* key, bool* value) {
        const Json* v = Find(key, false);
        if (v == nullptr) return;
        if (!v->is_boolean()) return Bad(key, "must be true or false", v);
        *value = v->get<bool>();
    }
    void String(const char* key, std::string* value, bool required = false) {
        const Json* v = Find(key, required);
        if (v == nullptr) return;
        if (!v->is_string() || v->get<std::string>().empty()) return Bad(key, "must be a non-empty string", v);
        *value = v->get<std::string>();
    }
    /// An array of `n` finite numbers (n <= 4); false if absent or bad.
    bool Numbers(const char* key, float* values, int n, Range range, bool required = false) {
        const Json* v = Find(key, required);
        if (v == nullptr) return false;
        if (!v->is_array() || v->size() != static_cast<std::size_t>(n)) {
            Bad(key, "must be an array of " + std::to_string(n) + " numbers", v);
            return false;
        }
        float tmp[4] = {};
        bool good = true;
        for (int i = 0; i < n; ++i) {
            const Json& e = (*v)[static_cast<std::size_t>(i)];
            const std::string at = Index(Join(path, key), static_cast<std::size_t>(i));
            if (!e.is_number()) {
                out->Add(at, "must be a number", &e);
                good = false;
                continue;
            }
            const float f = static_cast<float>(e.get<double>());
            if (!std::isfinite(e.get<double>()) || !std::isfinite(f)) {
                out->Add(at, kFiniteMessage, &e);
                good = false;
            } else if (BelowFloat(e.get<double>())) {
                out->Add(at, kUnderflowMessage, &e);
                good = false;
            } else if (range == Range::Positive && !(f > 0.0f)) {
                out->Add(at, "must be > 0", &e);
                good = false;
            } else if (range == Range::Fraction && !(f >= 0.0f && f <= 1.0f)) {
                out->Add(at, "must be in [0, 1]", &e);
                good = false;
            }
            tmp[i] = f;
        }
        if (good) std::copy(tmp, tmp + n, values);
        return good;
    }
    bool Vec3(const char* key, vec3* value, Range range = Range::Any, bool required = false) {
        float f[3];
        if (!Numbers(key, f, 3, range, required)) return false;
        *value = vec3(f[0], f[1], f[2]);
        return true;
    }
    /// A sub-object, or nullptr if absent (reported if required).
    const Json* Object(const char* key, bool required = false) { return Find(key, required); }
    /// An array of at most `limit` entries, or nullptr if absent or bad.
    const Json* Array(const char* key, std::size_t limit) {
        const Json* v = Find(key, false);
        if (v == nullptr) return nullptr;
        if (!v->is_array()) {
            Bad(key, "must be an array", v);
            return nullptr;
        }
        if (v->size() > limit) {
            const Json count = v->size();
            Bad(key, "has more than the limit of " + std::to_string(limit) + " entries", &count);
            return nullptr;
        }
        return v;
    }
    void Reject(const char* key, const std::string& why) {
        if (Has(key)) Bad(key, why, &obj.at(key));
        read.insert(key);
    }
    /// Reports every key that was never read.
    void Finish() {
        if (!ok) return;
        for (auto it = obj.begin(); it != obj.end(); ++it) {
            if (read.count(it.key()) == 0) out->Add(Join(path, it.key()), "unknown key");
        }
    }
    const std::string& Path() const { return path; }
    std::string PathOf(const char* key) const { return Join(path, key); }

private:
    const Json* Find(const char* key, bool required) {
        read.insert(key);
        if (!ok) return nullptr;
        auto it = obj.find(key);
        if (it == obj.end()) {
            if (required) out->Add(Join(path, key), "is required");
            return nullptr;
        }
        return &*it;
    }
    void Bad(const char* key, const std::string& message, const Json* value) {
        out->Add(Join(path, key), message, value);
    }

    const Json& obj;
    std::string path;
    Problems* out;
    bool ok = false;
    std::set<std::string> read;
};

/// world.soft: the soft solver's settings, in the ranges `--set soft-...` takes (ContactSolverParameters.h).
void ReadSoft(const Json& j, SoftSolverSettings* soft, Problems* problems) {
    using L = SoftSolverLimits;
    ObjectReader r(j, "world.soft", problems);
    r.Int("substeps", &soft->substeps, 1, L::kMaxSubsteps);
    r.Int("iterations", &soft->iterations, 1, L::kMaxIterations);
    r.Int("relaxIterations", &soft->relaxIterations, 0, L::kMaxIterations);
    r.FloatIn("contactHertz", &soft->contactHertz, L::kMinContactHertz, L::kMaxContactHertz);
    r.FloatIn("contactDampingRatio", &soft->contactDampingRatio, 0.0f, L::kMaxDampingRatio);
    r.FloatIn("maxPushoutSpeed", &soft->maxPushoutSpeed, 0.0f, L::kMaxPushoutSpeed);
    r.Float("speculativeMargin", &soft->speculativeMargin, Range::NonNegative);
    r.Float("linearSlop", &soft->linearSlop, Range::NonNegative);
    r.Float("restitutionThreshold", &soft->restitutionThreshold, Range::NonNegative);
    r.Float("warmStartFactor", &soft->warmStartFactor, Range::Fraction);
    r.Finish();
}

/// world.sleep: true or false, or an object of sleep settings (sleep on unless its `enabled` is false).
void ReadSleep(const Json& j, SleepSettings* sleep, Problems* problems) {
    if (j.is_boolean()) {
        sleep->enabled = j.get<bool>();
        return;
    }
    if (!j.is_object()) return problems->Add("world.sleep", "must be true, false or an object", &j);
    ObjectReader r(j, "world.sleep", problems);
    sleep->enabled = true;
    r.Bool("enabled", &sleep->enabled);
    r.Float("timeToSleep", &sleep->timeToSleep, Range::NonNegative);
    r.Float("linearSpeed", &sleep->linearSpeed, Range::NonNegative);
    r.Float("angularSpeed", &sleep->angularSpeed, Range::NonNegative);
    r.Finish();
}

/// world.step (docs/app.md, "Steps"): 0 for the host's step, or within --dt's range; a value that is not a whole
/// number of microseconds is rounded to the nearest one, with a note.
void ReadStep(const Json& j, ObjectReader* r, float* step, Problems* problems) {
    float given = 0.0f;
    r->FloatIn("step", &given, SceneLimits::kMinStep, SceneLimits::kMaxStep, true);
    if (!r->Has("step") || !j.at("step").is_number() || static_cast<float>(j.at("step").get<double>()) != given) return;
    bool exact = true;
    const long long micros = StepMicros(j.at("step").get<double>(), &exact);
    *step = static_cast<float>(static_cast<double>(micros) / static_cast<double>(kStepMicrosPerSecond));
    if (!exact) problems->Note("world.step", StepRoundedNote(j.at("step").dump(), micros));
}

void ReadWorld(const Json& j, SceneWorld* w, Problems* problems) {
    ObjectReader r(j, "world", problems);
    r.Vec3("gravity", &w->gravity);
    ReadStep(j, &r, &w->step, problems);
    // A named choice: absent keeps the default; a name `parse` does not know is refused with the valid ones.
    auto choice = [&](const char* key, const std::string& what, const std::string& ids, auto parse) {
        std::string name;
        r.String(key, &name);
        if (!name.empty() && !parse(name))
            problems->Add(std::string("world.") + key, "is not " + what + " (" + ids + ")", &j.at(key));
    };
    choice("integrator", "an integrator", IntegratorIds(),
           [&](const std::string& n) { return ParseIntegrator(n, &w->integrator); });
    choice("particleContact", "a particle contact", ParticleContactIds(),
           [&](const std::string& n) { return ParseParticleContact(n, &w->particleContact); });
    choice("jointModel", "a joint model", JointModelIds(),
           [&](const std::string& n) { return ParseJointModel(n, &w->jointModel); });
    choice("volumePositions", "a volume position update", VolumePositionsIds(),
           [&](const std::string& n) { return ParseVolumePositions(n, &w->volumePositions); });
    choice("contactSolver", "a contact solver", ContactSolverIds(),
           [&](const std::string& n) { return ParseContactSolver(n, &w->contactSolver); });
    r.Int("iterations", &w->iterations, 1, SceneLimits::kMaxIterations);
    r.Float("penetrationSlop", &w->penetrationSlop, Range::NonNegative);
    r.Bool("linearProjection", &w->linearProjection);
    r.Float("projectionFraction", &w->projectionFraction, Range::Fraction);
    r.Int("substeps", &w->maxSubsteps, 1, SceneLimits::kMaxSubsteps);
    r.Float("warmStartFactor", &w->warmStartFactor, Range::Fraction);
    r.Float("baumgarte", &w->baumgarte, Range::Fraction);
    r.Float("restitutionThreshold", &w->restitutionThreshold, Range::NonNegative);
    if (const Json* soft = r.Object("soft")) ReadSoft(*soft, &w->soft, problems);
    if (const Json* sleep = r.Object("sleep")) ReadSleep(*sleep, &w->sleep, problems);
    r.Finish();
}

void ReadCamera(const Json& j, SceneCamera* c, Problems* problems) {
    ObjectReader r(j, "camera", problems);
    r.Vec3("target", &c->target);
    float rot[2];
    if (r.Numbers("rotation", rot, 2, Range::Any)) c->rotation = vec2(rot[0], rot[1]);
    r.Float("zoom", &c->zoom, Range::Positive);
    r.Finish();
}

bool ParseKind(const std::string& text, SceneBodyKind* kind) {
    const std::pair<const char*, SceneBodyKind> kinds[] = {
        {"particle", SceneBodyKind::Particle}, {"sphere", SceneBodyKind::Sphere}, {"box", SceneBodyKind::Box}};
    const auto* it = std::find_if(std::begin(kinds), std::end(kinds), [&](const auto& k) { return text == k.first; });
    if (it == std::end(kinds)) return false;
    *kind = it->second;
    return true;
}

void ReadBody(const Json& j, const std::string& path, SceneBody* b, Problems* problems) {
    ObjectReader r(j, path, problems);
    if (!r.Valid()) return;
    r.String("id", &b->id, true);
    std::string type;
    r.String("type", &type, true);
    if (!type.empty() && !ParseKind(type, &b->kind)) {
        problems->Add(r.PathOf("type"), "must be particle, sphere or box", &j.at("type"));
    }
    const bool particle = b->kind == SceneBodyKind::Particle;
    if (particle) {
        b->restitution = 0.7f;
        b->velocityRetention = 0.95f;
    }
    r.Vec3("position", &b->position, Range::Any, true);
    r.Vec3("velocity", &b->velocity);
    r.FloatIn("mass", &b->mass, SceneLimits::kMinMass, SceneLimits::kMaxMass, true);
    r.Float("restitution", &b->restitution, Range::Fraction);
    r.Float("velocityRetention", &b->velocityRetention, Range::Fraction);
    float rgb[3];
    if (r.Numbers("color", rgb, 3, Range::Fraction)) {
        b->hasColor = true;
        b->color = vec3(rgb[0], rgb[1], rgb[2]);
    }
    if (particle) {
        const char* why = "is not a particle field (particles are points: no size, orientation, spin or friction)";
        for (const char* key :
             {"halfExtents", "radius", "euler", "quaternion", "angularVelocity", "friction", "velocityEpsilon"}) {
            r.Reject(key, why);
        }
    } else {
        if (b->kind == SceneBodyKind::Box) {
            r.Vec3("halfExtents", &b->halfExtents, Range::Positive);
            r.Reject("radius", "is a sphere field; boxes take halfExtents");
        } else {
            r.Float("radius", &b->radius, Range::Positive);
            r.Reject("halfExtents", "is a box field; spheres take radius");
        }
        if (r.Has("euler") && r.Has("quaternion")) {
            problems->Add(path, "gives both euler and quaternion; give one orientation");
        }
        r.Vec3("euler", &b->eulerDegrees);
        float q[4];
        if (r.Numbers("quaternion", q, 4, Range::Any)) {
            const float len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            if (!(len > 1e-6f) || !std::isfinite(len)) {
                problems->Add(r.PathOf("quaternion"), "must have a non-zero length", &j.at("quaternion"));
            } else {
                b->hasQuaternion = true;
                // Normalised unless already of unit length to 1e-6, so an exported orientation reads back exactly.
                b->orientation = quat(q[0], q[1], q[2], q[3]);
                if (std::fabs(len - 1.0f) > 1e-6f) b->orientation = Normalized(b->orientation);
            }
        }
        r.Vec3("angularVelocity", &b->angularVelocity);
        r.Float("friction", &b->friction, Range::NonNegative);
        r.Float("velocityEpsilon", &b->velocityEpsilon, Range::NonNegative);
    }
    r.Finish();
}

void ReadConstraint(const Json& j, const std::string& path, SceneConstraint* c, Problems* problems) {
    ObjectReader r(j, path, problems);
    r.Vec3("position", &c->position, Range::Any, true);
    r.Vec3("halfExtents", &c->halfExtents, Range::Positive, true);
    r.Vec3("euler", &c->eulerDegrees);
    r.Finish();
}

/// Resolves the body id under `key` to an index of a particle; reports dangling ids and non-particles.
bool ReadParticleRef(ObjectReader* r, const Json& j, const char* key, const std::map<std::string, std::size_t>& ids,
                     const std::vector<SceneBody>& bodies, std::size_t* index, Problems* problems) {
    std::string id;
    r->String(key, &id, true);
    if (id.empty()) return false;
    auto it = ids.find(id);
    if (it == ids.end()) {
        problems->Add(r->PathOf(key), "names no body", &j.at(key));
        return false;
    }
    if (bodies[it->second].kind != SceneBodyKind::Particle) {
        problems->Add(r->PathOf(key), "must name a particle", &j.at(key));
        return false;
    }
    *index = it->second;
    return true;
}

void ReadCloth(const Json& j, const std::string& path, SceneCloth* c, Problems* problems) {
    ObjectReader r(j, path, problems);
    r.Int("gridSize", &c->gridSize, 3, SceneLimits::kMaxClothGrid, true);
    r.Float("spacing", &c->spacing, Range::Positive, true);
    r.Vec3("position", &c->position, Range::Any, true);
    r.FloatIn("particleMass", &c->particleMass, SceneLimits::kMinMass, SceneLimits::kMaxMass);
    r.Float("velocityRetention", &c->velocityRetention, Range::Fraction);
    struct Kind {
        const char* key;
        float* k;
        float* b;
    } kinds[] = {{"structural", &c->structuralStiffness, &c->structuralDamping},
                 {"shear", &c->shearStiffness, &c->shearDamping},
                 {"bend", &c->bendStiffness, &c->bendDamping}};
    for (const Kind& kind : kinds) {
        const Json* v = r.Object(kind.key);
        if (v == nullptr) continue;
        ObjectReader s(*v, r.PathOf(kind.key), problems);
        s.Float("stiffness", kind.k, Range::NonNegative, true);
        s.Float("damping", kind.b, Range::NonNegative);
        s.Finish();
    }
    r.Finish();
}

/// "model" and "budget" (docs/scenes.md, "Error budget"). The bound is checked as `--set error-budget=` checks it
/// (finite, > 0, within the key's range: AddAutoModelParameters), so a file and the command line take the same.
void ReadAutoModel(const Json& root, ObjectReader* r, AutoModelRequest* request, Problems* problems) {
    std::string model;
    r->String("model", &model);
    if (model == "auto") {
        request->model = 1;
    } else if (!model.empty() && model != "fixed") {
        problems->Add("model", "must be \"fixed\" or \"auto\"", &root.at("model"));
    }
    const Json* budget = r->Object("budget");
    if (budget == nullptr) {
        if (request->Auto()) problems->Add("budget", "is required when model is \"auto\" (e.g. {\"bound\": 0.01})");
        return;
    }
    ObjectReader b(*budget, "budget", problems);
    if (!b.Valid()) return;
    std::string name;
    b.String("quantity", &name);
    BudgetQuantity quantity = BudgetQuantity::Position;
    if (!name.empty() && !ParseBudgetQuantity(name, &quantity)) {
        problems->Add("budget.quantity", "must be position, energy or constraint", &budget->at("quantity"));
    }
    request->quantity = static_cast<int>(quantity);
    if (!b.Has("bound")) problems->Add("budget.bound", "is required");
    b.FloatIn("bound", &request->bound, AutoModelRequest::kMinBound, AutoModelRequest::kMaxBound);
    b.Finish();
}

void ReadTop(const Json& root, SceneDescription* d, Problems* problems) {
    ObjectReader r(root, "", problems);
    if (!r.Valid()) return;
    r.Int("format", &d->format, 0, 1000000, true);
    if (r.Has("format") && root.at("format").is_number_integer() && d->format != kSceneFormatVersion) {
        problems->Add("format", "is not a version this build reads (" + std::to_string(kSceneFormatVersion) + ")",
                      &root.at("format"));
    }
    r.String("name", &d->name, true);
    r.FloatIn("duration", &d->duration, SceneLimits::kMinDuration, SceneLimits::kMaxDuration);
    ReadAutoModel(root, &r, &d->autoModel, problems);
    if (const Json* w = r.Object("world")) ReadWorld(*w, &d->world, problems);
    if (const Json* c = r.Object("camera")) ReadCamera(*c, &d->camera, problems);

    std::map<std::string, std::size_t> ids;
    if (const Json* bodies = r.Array("bodies", SceneLimits::kMaxBodies)) {
        d->bodies.resize(bodies->size());
        for (std::size_t i = 0; i < bodies->size(); ++i) {
            const std::string path = Index("bodies", i);
            ReadBody((*bodies)[i], path, &d->bodies[i], problems);
            const std::string& id = d->bodies[i].id;
            if (id.empty()) continue;
            if (!ids.emplace(id, i).second) {
                problems->Add(path + ".id", "duplicates the id of bodies[" + std::to_string(ids[id]) + "]",
                              &(*bodies)[i].at("id"));
            }
        }
    }
    if (const Json* list = r.Array("constraints", SceneLimits::kMaxConstraints)) {
        d->constraints.resize(list->size());
        for (std::size_t i = 0; i < list->size(); ++i) {
            ReadConstraint((*list)[i], Index("constraints", i), &d->constraints[i], problems);
        }
    }
    if (const Json* list = r.Array("springs", SceneLimits::kMaxSprings)) {
        d->springs.resize(list->size());
        for (std::size_t i = 0; i < list->size(); ++i) {
            const Json& j = (*list)[i];
            SceneSpring& s = d->springs[i];
            ObjectReader sr(j, Index("springs", i), problems);
            if (!sr.Valid()) continue;
            const bool a = ReadParticleRef(&sr, j, "a", ids, d->bodies, &s.a, problems);
            const bool b = ReadParticleRef(&sr, j, "b", ids, d->bodies, &s.b, problems);
            if (a && b && s.a == s.b) problems->Add(sr.PathOf("b"), "must differ from a", &j.at("b"));
            sr.Float("stiffness", &s.stiffness, Range::NonNegative, true);
            sr.Float("damping", &s.damping, Range::NonNegative);
            sr.Float("restLength", &s.restLength, Range::NonNegative, true);
            sr.Finish();
        }
    }
    if (const Json* list = r.Array("joints", SceneLimits::kMaxJoints)) {
        d->joints.resize(list->size());
        for (std::size_t i = 0; i < list->size(); ++i) {
            const Json& j = (*list)[i];
            SceneJoint& s = d->joints[i];
            ObjectReader jr(j, Index("joints", i), problems);
            if (!jr.Valid()) continue;
            const bool a = ReadParticleRef(&jr, j, "a", ids, d->bodies, &s.a, problems);
            const bool b = ReadParticleRef(&jr, j, "b", ids, d->bodies, &s.b, problems);
            if (a && b && s.a == s.b) problems->Add(jr.PathOf("b"), "must differ from a", &j.at("b"));
            jr.Float("length", &s.length, Range::Positive, true);
            jr.Finish();
        }
    }
    if (const Json* list = r.Array("cloths", SceneLimits::kMaxCloths)) {
        d->cloths.resize(list->size());
        for (std::size_t i = 0; i < list->size(); ++i)
            ReadCloth((*list)[i], Index("cloths", i), &d->cloths[i], problems);
    }
    r.Finish();
}

}  // namespace

bool ParseSceneText(const std::string& text, const std::string& fileName, SceneDescription* out,
                    std::vector<std::string>* errors, std::vector<std::string>* notes) {
    Problems problems(fileName, errors, notes);
    if (text.size() > SceneLimits::kMaxFileBytes) {
        problems.Add("", "is larger than the limit of " + std::to_string(SceneLimits::kMaxFileBytes) + " bytes");
        return false;
    }
    // Nesting is measured before parsing: a deep text is refused in one linear pass, before the parser or the
    // duplicate-key check builds anything per level.
    const JsonNesting nesting = MeasureNesting(text, SceneLimits::kMaxNesting);
    if (nesting.over) {
        int line = 0, column = 0;
        LineAndColumn(text, nesting.offset, &line, &column);
        errors->push_back(fileName + ":" + std::to_string(line) + ":" + std::to_string(column) +
                          ": arrays and objects nest " + std::to_string(nesting.depth) +
                          " levels deep, over the limit of " + std::to_string(SceneLimits::kMaxNesting));
        return false;
    }
    Json root;
    try {
        root = Json::parse(text);
    } catch (const Json::parse_error& e) {
        // e.byte is 1-based: the byte at which the parser stopped.
        int line = 0, column = 0;
        LineAndColumn(text, e.byte > 0 ? e.byte - 1 : 0, &line, &column);
        std::string what = e.what();
        const std::size_t cut = what.find("syntax error");
        if (cut != std::string::npos) what = what.substr(cut);
        errors->push_back(fileName + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + what);
        return false;
    } catch (const Json::out_of_range& e) {
        // A number beyond double range ("number overflow parsing '1e999'"): no byte position is given, so the
        // quoted token is looked up in the text for its line and column.
        std::string what = e.what();
        const std::size_t open = what.find('\''), close = what.rfind('\'');
        std::string where = fileName;
        if (open != std::string::npos && close > open) {
            const std::size_t at = text.find(what.substr(open + 1, close - open - 1));
            int line = 0, column = 0;
            LineAndColumn(text, at == std::string::npos ? 0 : at, &line, &column);
            where += ":" + std::to_string(line) + ":" + std::to_string(column);
            what = "number is not finite: " + what.substr(open);
        }
        errors->push_back(where + ": " + what);
        return false;
    }
    // The parser keeps the last of a key given twice; a scene file refuses it, at the second one.
    DuplicateKey duplicate;
    if (FindDuplicateKey(text, &duplicate)) {
        int line = 0, column = 0;
        LineAndColumn(text, duplicate.offset, &line, &column);
        errors->push_back(fileName + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
                          Join(duplicate.objectPath, duplicate.key) + ": duplicate key \"" + duplicate.key +
                          "\" (a key may be given once per object)");
        return false;
    }
    *out = SceneDescription();
    ReadTop(root, out, &problems);
    return problems.Count() == 0;
}
