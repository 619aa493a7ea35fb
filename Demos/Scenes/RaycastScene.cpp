#include "Demos/Scenes/RaycastScene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <system_error>
#include <vector>

#include "Physics/Geometry/ObjLoader.h"

RaycastScene::RaycastScene()
    : obb({-4.0f, -2.0f, 0.0f}, {1.0f, 1.0f, 1.0f}, Rotation3x3(30.0f, 20.0f, 0.0f)),
      plane(FromTriangle(Triangle({4.0f, -1.0f, 0.0f}, {3.0f, -3.0f, 0.0f}, {3.0f, -3.0f, 1.0f}))),
      triangle({0.0f, 3.0f, 0.0f}, {-1.0f, 1.0f, 0.0f}, {1.0f, 1.0f, 0.0f}) {
    model.position = kModelPosition;
}

bool RaycastScene::LoadModel(const std::string& path, std::string* error) {
    model.content = nullptr;
    mesh = Mesh();
    if (!LoadMesh(path, &mesh, error)) return false;
    model.content = &mesh;
    return true;
}

RaycastResult RaycastScene::CastAll(const Ray& ray, Shape* shape) const {
    RaycastResult best;
    ResetRaycastResult(&best);
    Shape bestShape = Shape::None;
    auto consider = [&](bool hit, const RaycastResult& r, Shape s) {
        if (hit && r.t >= 0.0f && (!best.hit || r.t < best.t)) {
            best = r;
            bestShape = s;
        }
    };
    RaycastResult r;
    consider(Raycast(sphere, ray, &r), r, Shape::Sphere);
    consider(Raycast(aabb, ray, &r), r, Shape::AABB);
    consider(Raycast(obb, ray, &r), r, Shape::OBB);
    consider(Raycast(plane, ray, &r), r, Shape::Plane);
    consider(Raycast(triangle, ray, &r), r, Shape::Triangle);
    if (HasModel()) consider(Raycast(model, ray, &r), r, Shape::Model);
    if (shape != nullptr) *shape = bestShape;
    return best;
}

vec2 RaycastScene::ScriptedCursor(int frame, float speed, const vec2& viewportSize) {
    // Phase in [0, 1): first half sweeps the upper row left to right, second half the lower row back.
    const double sweeps = static_cast<double>(frame) * static_cast<double>(speed) / kSweepFrames;
    const float phase = static_cast<float>(sweeps - std::floor(sweeps));
    const bool upper = phase < 0.5f;
    const float s = upper ? phase * 2.0f : (1.0f - phase) * 2.0f;  // 0 -> 1 -> 0
    // From the default camera (zoom 10, 60 degree vertical fov) world y = +-2 at z = 0 sits at
    // 0.5 -+ 2 / (10 tan 30) / 2 of the height.
    const float rowOffset = 2.0f / (10.0f * std::tan(30.0f * 3.14159265f / 180.0f)) * 0.5f;
    const float x = (0.1f + 0.8f * s) * viewportSize.x;
    const float y = (upper ? 0.5f - rowOffset : 0.5f + rowOffset) * viewportSize.y;
    return vec2(x, y);
}

std::string FirstObjFile(const std::string& directory) {
    std::error_code ec;
    std::vector<std::string> found;
    for (std::filesystem::directory_iterator it(directory, ec), end; !ec && it != end; it.increment(ec))
        if (it->is_regular_file(ec) && it->path().extension() == ".obj") found.push_back(it->path().string());
    if (found.empty()) return "";
    std::sort(found.begin(), found.end());
    return found.front();
}

void AddRaycastParameters(ParameterSet* set, RaycastParams* params) {
    using Widget = ParameterSet::Widget;
    set->AddBool("script", &params->script,
                 "sweep a scripted pick ray across the screen (0: no pick, as before a click)")
        .OnPanel(Widget::Checkbox("Scripted pick"));
    set->AddFloat("speed", &params->speed, 0.0f, 8.0f, "sweeps per 240 output frames")
        .OnPanel(Widget::Slider("Speed").Width(100.0f).SameLine().Format("%.2f"));
}
