#pragma once
// Camera and OrbitCamera (docs/book-reference.md §1.4). GL-free: they only produce matrices.

#include "Math/matrices.h"
#include "Math/vectors.h"

class Camera {
public:
    Camera();
    virtual ~Camera() = default;

    mat4 GetWorldMatrix() const { return m_matWorld; }
    /// Fast (rigid) inverse of the world matrix, re-orthonormalised first if needed.
    mat4 GetViewMatrix();
    mat4 GetProjectionMatrix() const { return m_matProj; }
    float GetAspect() const { return m_nAspect; }
    bool IsOrthographic() const { return m_nProjectionMode == 1; }
    bool IsPerspective() const { return m_nProjectionMode == 0; }
    bool IsOrthoNormal() const;
    void OrthoNormalize();
    void Resize(int width, int height);
    void Perspective(float fov, float aspect, float zNear, float zFar);
    void Orthographic(float width, float height, float zNear, float zFar);
    void SetProjection(const mat4& projection);
    void SetWorld(const mat4& view);

protected:
    float m_nFov, m_nAspect, m_nNear, m_nFar, m_nWidth, m_nHeight;
    mat4 m_matWorld;
    mat4 m_matProj;
    int m_nProjectionMode;  // 0 perspective, 1 ortho, 2 user
};

class OrbitCamera : public Camera {
public:
    OrbitCamera();
    /// delta in window fractions; rotation scales with zoom distance, as the book.
    void Rotate(const vec2& deltaRot, float deltaTime);
    void Zoom(float deltaZoom, float deltaTime);
    void Pan(const vec2& delataPan, float deltaTime);
    /// Rebuilds the world matrix from target, zoom and rotation (must run before the first frame).
    void Update(float dt);
    void SetTarget(const vec3& newTarget) { target = newTarget; }
    void SetZoom(float zoom) { zoomDistance = zoom; }
    void SetRotation(const vec2& rotation) { currentRotation = rotation; }
    vec3 GetTarget() const { return target; }
    float GetZoom() const { return zoomDistance; }
    vec2 GetRotation() const { return currentRotation; }
    /// Eye position implied by target, zoom and rotation.
    vec3 GetEye() const;
    float ClampAngle(float angle, float min, float max);

protected:
    vec3 target;
    vec2 panSpeed;
    float zoomDistance;
    vec2 zoomDistanceLimit;  // x = min, y = max
    float zoomSpeed;
    vec2 rotationSpeed;
    vec2 yRotationLimit;  // x = min, y = max
    vec2 currentRotation;
};
