// Camera and OrbitCamera (docs/book-reference.md §1.4). Matrices only; the drawing layer loads them into GL.
#include "Application/View/Camera.h"

#include <cmath>

#include "Math/Compare.h"

namespace {

vec3 Row(const mat4& m, int i) { return vec3(m[i][0], m[i][1], m[i][2]); }
void SetRow(mat4& m, int i, const vec3& v) {
    m[i][0] = v.x;
    m[i][1] = v.y;
    m[i][2] = v.z;
}

}  // namespace

/// Book defaults: fov 60 degrees, aspect 1.3, near 0.01, far 1000, perspective, identity world.
Camera::Camera()
    : m_nFov(60.0f),
      m_nAspect(1.3f),
      m_nNear(0.01f),
      m_nFar(1000.0f),
      m_nWidth(1.0f),
      m_nHeight(1.0f),
      m_nProjectionMode(0) {
    m_matProj = Projection(m_nFov, m_nAspect, m_nNear, m_nFar);
}

/// True if the world matrix's first three rows are unit length and mutually perpendicular (CMP, 0.005).
bool Camera::IsOrthoNormal() const {
    const vec3 right = Row(m_matWorld, 0), up = Row(m_matWorld, 1), forward = Row(m_matWorld, 2);
    if (!CMP(Dot(right, right), 1.0f) || !CMP(Dot(up, up), 1.0f) || !CMP(Dot(forward, forward), 1.0f)) return false;
    return CMP(Dot(right, up), 0.0f) && CMP(Dot(right, forward), 0.0f) && CMP(Dot(up, forward), 0.0f);
}

/// Rebuilds the rotation rows keeping forward: right = up x forward, up = forward x right (book); the
/// translation row is kept.
void Camera::OrthoNormalize() {
    const vec3 forward = Normalized(Row(m_matWorld, 2));
    const vec3 right = Normalized(Cross(Row(m_matWorld, 1), forward));
    const vec3 up = Cross(forward, right);
    SetRow(m_matWorld, 0, right);
    SetRow(m_matWorld, 1, up);
    SetRow(m_matWorld, 2, forward);
}

/// World-to-view matrix: the rigid inverse of the (re-orthonormalised) camera world matrix.
mat4 Camera::GetViewMatrix() {
    if (!IsOrthoNormal()) OrthoNormalize();
    return FastInverse(m_matWorld);
}

/// New viewport size in pixels; aspect = width / height (a zero height is treated as 1). Rebuilds a
/// perspective or orthographic projection; a user projection is left alone.
void Camera::Resize(int width, int height) {
    m_nWidth = static_cast<float>(width);
    m_nHeight = static_cast<float>(height > 0 ? height : 1);
    m_nAspect = m_nWidth / m_nHeight;
    if (m_nProjectionMode == 0) {
        m_matProj = Projection(m_nFov, m_nAspect, m_nNear, m_nFar);
    } else if (m_nProjectionMode == 1) {
        const float halfW = m_nWidth * 0.5f, halfH = m_nHeight * 0.5f;
        m_matProj = Ortho(-halfW, halfW, -halfH, halfH, m_nNear, m_nFar);
    }
}

/// D3D-style perspective (vertical fov in degrees, view z in [near, far] -> NDC z in [0, 1]).
void Camera::Perspective(float fov, float aspect, float zNear, float zFar) {
    m_nFov = fov;
    m_nAspect = aspect;
    m_nNear = zNear;
    m_nFar = zFar;
    m_matProj = Projection(fov, aspect, zNear, zFar);
    m_nProjectionMode = 0;
}

/// Orthographic projection of a width x height (world units) box centred on the view axis.
void Camera::Orthographic(float width, float height, float zNear, float zFar) {
    m_nWidth = width;
    m_nHeight = height;
    m_nNear = zNear;
    m_nFar = zFar;
    const float halfW = width * 0.5f, halfH = height * 0.5f;
    m_matProj = Ortho(-halfW, halfW, -halfH, halfH, zNear, zFar);
    m_nProjectionMode = 1;
}

/// A user projection; Resize no longer rebuilds it.
void Camera::SetProjection(const mat4& projection) {
    m_matProj = projection;
    m_nProjectionMode = 2;
}

/// Sets the camera's world (camera-to-world) matrix.
void Camera::SetWorld(const mat4& view) { m_matWorld = view; }

/// Book defaults: target 0, zoom 10 in [3, 15], zoom speed 200, rotation speed (250, 120), pitch limits
/// [-20, 80] degrees, pan speed (180, 180), rotation (0, 0).
OrbitCamera::OrbitCamera()
    : target(0, 0, 0),
      panSpeed(180.0f, 180.0f),
      zoomDistance(10.0f),
      zoomDistanceLimit(3.0f, 15.0f),
      zoomSpeed(200.0f),
      rotationSpeed(250.0f, 120.0f),
      yRotationLimit(-20.0f, 80.0f),
      currentRotation(0.0f, 0.0f) {}

/// Wraps into [-360, 360] by whole turns, then clamps to [min, max] (degrees).
float OrbitCamera::ClampAngle(float angle, float min, float max) {
    while (angle < -360.0f) angle += 360.0f;
    while (angle > 360.0f) angle -= 360.0f;
    if (angle < min) angle = min;
    if (angle > max) angle = max;
    return angle;
}

/// Yaw (x) and pitch (y) advance by delta * speed * zoom * dt; yaw wraps, pitch is clamped to the limits.
void OrbitCamera::Rotate(const vec2& deltaRot, float deltaTime) {
    currentRotation.x += deltaRot.x * rotationSpeed.x * zoomDistance * deltaTime;
    currentRotation.y += deltaRot.y * rotationSpeed.y * zoomDistance * deltaTime;
    currentRotation.x = ClampAngle(currentRotation.x, -360.0f, 360.0f);
    currentRotation.y = ClampAngle(currentRotation.y, yRotationLimit.x, yRotationLimit.y);
}

/// zoom += delta * speed * dt, clamped to the zoom limits.
void OrbitCamera::Zoom(float deltaZoom, float deltaTime) {
    zoomDistance += deltaZoom * zoomSpeed * deltaTime;
    if (zoomDistance < zoomDistanceLimit.x) zoomDistance = zoomDistanceLimit.x;
    if (zoomDistance > zoomDistanceLimit.y) zoomDistance = zoomDistanceLimit.y;
}

/// Moves the target along the camera's right axis (x) and world up (y); then the book repo's hack (not in the
/// printed book): keep the eye where it is and slide the target along the view direction so that the zoom is
/// the middle of its range.
void OrbitCamera::Pan(const vec2& delataPan, float deltaTime) {
    const vec3 right = Row(m_matWorld, 0);
    target = target - right * (delataPan.x * panSpeed.x * deltaTime);
    target = target + vec3(0, 1, 0) * (delataPan.y * panSpeed.y * deltaTime);

    const float midZoom = zoomDistanceLimit.x + (zoomDistanceLimit.y - zoomDistanceLimit.x) * 0.5f;
    const vec3 eye = GetEye();
    const vec3 forward = Normalized(target - eye);
    target = eye + forward * midZoom;
    zoomDistance = midZoom;
}

/// Eye = target + (0, 0, -zoom) * Rotation3x3(pitch = rotation.y, yaw = rotation.x, 0); in closed form
/// target + zoom * (-cos p sin y, sin p, -cos p cos y).
vec3 OrbitCamera::GetEye() const {
    const mat3 orient = Rotation3x3(currentRotation.y, currentRotation.x, 0.0f);
    return target + MultiplyVector(vec3(0, 0, -zoomDistance), orient);
}

/// Rebuilds the world matrix as the inverse of LookAt(eye, target, +Y). dt is unused (as the book).
void OrbitCamera::Update(float /*dt*/) { m_matWorld = FastInverse(LookAt(GetEye(), target, vec3(0, 1, 0))); }
