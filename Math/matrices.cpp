#include "Math/matrices.h"

#include <cmath>

#include "Math/Compare.h"

namespace {

template <int N>
bool ElementsEqual(const float* a, const float* b) {
    for (int i = 0; i < N; ++i)
        if (!CMP(a[i], b[i])) return false;
    return true;
}

template <int N>
float RowLengthProduct(const float* m) {
    float product = 1.0f;
    for (int r = 0; r < N; ++r) {
        float sq = 0.0f;
        for (int c = 0; c < N; ++c) sq += m[r * N + c] * m[r * N + c];
        product *= std::sqrt(sq);
    }
    return product;
}

// Relative singularity test against the Hadamard bound |det| <= prod |row_i| (erratum 5.2-10).
bool SingularDet(float det, float rowProduct) {
    if (!std::isfinite(det) || !(rowProduct > 0.0f)) return true;
    return std::fabs(det) <= 1e-6f * rowProduct;
}

}  // namespace

mat3 ZeroMat3() { return mat3(0, 0, 0, 0, 0, 0, 0, 0, 0); }
mat4 ZeroMat4() { return mat4(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0); }
vec3 GetRow(const mat3& m, int row) { return {m[row][0], m[row][1], m[row][2]}; }

bool operator==(const mat2& l, const mat2& r) { return ElementsEqual<4>(l.asArray, r.asArray); }
bool operator==(const mat3& l, const mat3& r) { return ElementsEqual<9>(l.asArray, r.asArray); }
bool operator==(const mat4& l, const mat4& r) { return ElementsEqual<16>(l.asArray, r.asArray); }
bool operator!=(const mat2& l, const mat2& r) { return !(l == r); }
bool operator!=(const mat3& l, const mat3& r) { return !(l == r); }
bool operator!=(const mat4& l, const mat4& r) { return !(l == r); }

bool Multiply(float* out, const float* matA, int aRows, int aCols, const float* matB, int bRows, int bCols) {
    if (aCols != bRows) return false;
    for (int i = 0; i < aRows; ++i) {
        for (int j = 0; j < bCols; ++j) {
            float sum = 0.0f;
            for (int k = 0; k < bRows; ++k) sum += matA[aCols * i + k] * matB[bCols * k + j];
            out[bCols * i + j] = sum;
        }
    }
    return true;
}

void Transpose(const float* srcMat, float* dstMat, int srcRows, int srcCols) {
    for (int i = 0; i < srcRows * srcCols; ++i) {
        const int row = i / srcRows;
        const int col = i % srcRows;
        dstMat[i] = srcMat[srcCols * col + row];
    }
}

mat2 Transpose(const mat2& m) {
    mat2 r;
    Transpose(m.asArray, r.asArray, 2, 2);
    return r;
}
mat3 Transpose(const mat3& m) {
    mat3 r;
    Transpose(m.asArray, r.asArray, 3, 3);
    return r;
}
mat4 Transpose(const mat4& m) {
    mat4 r;
    Transpose(m.asArray, r.asArray, 4, 4);
    return r;
}

mat2 operator*(const mat2& m, float s) {
    mat2 r;
    for (int i = 0; i < 4; ++i) r.asArray[i] = m.asArray[i] * s;
    return r;
}
mat3 operator*(const mat3& m, float s) {
    mat3 r;
    for (int i = 0; i < 9; ++i) r.asArray[i] = m.asArray[i] * s;
    return r;
}
mat4 operator*(const mat4& m, float s) {
    mat4 r;
    for (int i = 0; i < 16; ++i) r.asArray[i] = m.asArray[i] * s;
    return r;
}
mat2 operator*(const mat2& a, const mat2& b) {
    mat2 r;
    Multiply(r.asArray, a.asArray, 2, 2, b.asArray, 2, 2);
    return r;
}
mat3 operator*(const mat3& a, const mat3& b) {
    mat3 r;
    Multiply(r.asArray, a.asArray, 3, 3, b.asArray, 3, 3);
    return r;
}
mat4 operator*(const mat4& a, const mat4& b) {
    mat4 r;
    Multiply(r.asArray, a.asArray, 4, 4, b.asArray, 4, 4);
    return r;
}
mat3 operator+(const mat3& a, const mat3& b) {
    mat3 r;
    for (int i = 0; i < 9; ++i) r.asArray[i] = a.asArray[i] + b.asArray[i];
    return r;
}

float Determinant(const mat2& m) { return m.asArray[0] * m.asArray[3] - m.asArray[1] * m.asArray[2]; }

mat2 Cut(const mat3& m, int row, int col) {
    mat2 r;
    int index = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (i != row && j != col) r.asArray[index++] = m[i][j];
    return r;
}
mat3 Cut(const mat4& m, int row, int col) {
    mat3 r;
    int index = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (i != row && j != col) r.asArray[index++] = m[i][j];
    return r;
}

mat2 Minor(const mat2& m) { return mat2(m.asArray[3], m.asArray[2], m.asArray[1], m.asArray[0]); }
mat3 Minor(const mat3& m) {
    mat3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[i][j] = Determinant(Cut(m, i, j));
    return r;
}
mat4 Minor(const mat4& m) {
    mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[i][j] = Determinant(Cut(m, i, j));
    return r;
}

template <typename M, int N>
static M CofactorOf(const M& minor) {
    M r;
    for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) r[i][j] = minor[i][j] * (((i + j) % 2 == 0) ? 1.0f : -1.0f);
    return r;
}
mat2 Cofactor(const mat2& m) { return CofactorOf<mat2, 2>(Minor(m)); }
mat3 Cofactor(const mat3& m) { return CofactorOf<mat3, 3>(Minor(m)); }
mat4 Cofactor(const mat4& m) { return CofactorOf<mat4, 4>(Minor(m)); }

float Determinant(const mat3& m) {
    const mat3 cof = Cofactor(m);
    float result = 0.0f;
    for (int j = 0; j < 3; ++j) result += m[0][j] * cof[0][j];
    return result;
}
float Determinant(const mat4& m) {
    const mat4 cof = Cofactor(m);
    float result = 0.0f;
    for (int j = 0; j < 4; ++j) result += m[0][j] * cof[0][j];
    return result;
}

mat2 Adjugate(const mat2& m) { return Transpose(Cofactor(m)); }
mat3 Adjugate(const mat3& m) { return Transpose(Cofactor(m)); }
mat4 Adjugate(const mat4& m) { return Transpose(Cofactor(m)); }

bool IsSingular(const mat2& m) { return SingularDet(Determinant(m), RowLengthProduct<2>(m.asArray)); }
bool IsSingular(const mat3& m) { return SingularDet(Determinant(m), RowLengthProduct<3>(m.asArray)); }
bool IsSingular(const mat4& m) { return SingularDet(Determinant(m), RowLengthProduct<4>(m.asArray)); }

mat2 Inverse(const mat2& m) {
    const float det = Determinant(m);
    if (SingularDet(det, RowLengthProduct<2>(m.asArray))) return mat2();
    return Adjugate(m) * (1.0f / det);
}
mat3 Inverse(const mat3& m) {
    const float det = Determinant(m);
    if (SingularDet(det, RowLengthProduct<3>(m.asArray))) return mat3();
    return Adjugate(m) * (1.0f / det);
}
mat4 Inverse(const mat4& m) {
    const float det = Determinant(m);
    if (SingularDet(det, RowLengthProduct<4>(m.asArray))) return mat4();
    return Adjugate(m) * (1.0f / det);
}

mat4 ToColumnMajor(const mat4& m) { return Transpose(m); }
mat3 ToColumnMajor(const mat3& m) { return Transpose(m); }
mat4 FromColumnMajor(const mat4& m) { return Transpose(m); }
mat4 FromColumnMajor(const float* input) {
    mat4 r;
    for (int i = 0; i < 16; ++i) r.asArray[i] = input[i];
    return Transpose(r);
}

mat4 Translation(float x, float y, float z) { return mat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, y, z, 1); }
mat4 Translation(const vec3& pos) { return Translation(pos.x, pos.y, pos.z); }
vec3 GetTranslation(const mat4& m) { return {m[3][0], m[3][1], m[3][2]}; }
mat4 Translate(float x, float y, float z) { return Translation(x, y, z); }
mat4 Translate(const vec3& pos) { return Translation(pos); }
mat4 FromMat3(const mat3& m) {
    mat4 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[i][j] = m[i][j];
    return r;
}
mat4 Scale(float x, float y, float z) { return mat4(x, 0, 0, 0, 0, y, 0, 0, 0, 0, z, 0, 0, 0, 0, 1); }
mat4 Scale(const vec3& s) { return Scale(s.x, s.y, s.z); }
vec3 GetScale(const mat4& m) { return {m[0][0], m[1][1], m[2][2]}; }

mat3 XRotation3x3(float angle) {
    const float a = DEG2RAD(angle);
    const float c = std::cos(a), s = std::sin(a);
    return mat3(1, 0, 0, 0, c, s, 0, -s, c);
}
mat3 YRotation3x3(float angle) {
    const float a = DEG2RAD(angle);
    const float c = std::cos(a), s = std::sin(a);
    return mat3(c, 0, -s, 0, 1, 0, s, 0, c);
}
mat3 ZRotation3x3(float angle) {
    const float a = DEG2RAD(angle);
    const float c = std::cos(a), s = std::sin(a);
    return mat3(c, s, 0, -s, c, 0, 0, 0, 1);
}
mat4 XRotation(float angle) { return FromMat3(XRotation3x3(angle)); }
mat4 YRotation(float angle) { return FromMat3(YRotation3x3(angle)); }
mat4 ZRotation(float angle) { return FromMat3(ZRotation3x3(angle)); }
mat3 Rotation3x3(float pitch, float yaw, float roll) {
    return ZRotation3x3(roll) * XRotation3x3(pitch) * YRotation3x3(yaw);
}
mat4 Rotation(float pitch, float yaw, float roll) { return FromMat3(Rotation3x3(pitch, yaw, roll)); }
mat4 YawPitchRoll(float yaw, float pitch, float roll) { return Rotation(pitch, yaw, roll); }

mat3 AxisAngle3x3(const vec3& axis, float angle) {
    const vec3 n = Normalized(axis);
    if (MagnitudeSq(n) == 0.0f) return mat3();
    const float a = DEG2RAD(angle);
    const float c = std::cos(a), s = std::sin(a), t = 1.0f - c;
    const float x = n.x, y = n.y, z = n.z;
    return mat3(t * x * x + c, t * x * y + s * z, t * x * z - s * y,  //
                t * x * y - s * z, t * y * y + c, t * y * z + s * x,  //
                t * x * z + s * y, t * y * z - s * x, t * z * z + c);
}
mat4 AxisAngle(const vec3& axis, float angle) { return FromMat3(AxisAngle3x3(axis, angle)); }

vec3 MultiplyPoint(const vec3& v, const mat4& m) {
    return {v.x * m[0][0] + v.y * m[1][0] + v.z * m[2][0] + m[3][0],
            v.x * m[0][1] + v.y * m[1][1] + v.z * m[2][1] + m[3][1],
            v.x * m[0][2] + v.y * m[1][2] + v.z * m[2][2] + m[3][2]};
}
vec3 MultiplyVector(const vec3& v, const mat4& m) {
    return {v.x * m[0][0] + v.y * m[1][0] + v.z * m[2][0], v.x * m[0][1] + v.y * m[1][1] + v.z * m[2][1],
            v.x * m[0][2] + v.y * m[1][2] + v.z * m[2][2]};
}
vec3 MultiplyVector(const vec3& v, const mat3& m) {
    return {v.x * m[0][0] + v.y * m[1][0] + v.z * m[2][0], v.x * m[0][1] + v.y * m[1][1] + v.z * m[2][1],
            v.x * m[0][2] + v.y * m[1][2] + v.z * m[2][2]};
}

mat4 Transform(const vec3& scale, const vec3& eulerRotation, const vec3& translate) {
    return Scale(scale) * Rotation(eulerRotation.x, eulerRotation.y, eulerRotation.z) * Translation(translate);
}
mat4 Transform(const vec3& scale, const vec3& rotationAxis, float rotationAngle, const vec3& translate) {
    return Scale(scale) * AxisAngle(rotationAxis, rotationAngle) * Translation(translate);
}

mat4 LookAt(const vec3& position, const vec3& target, const vec3& up) {
    vec3 forward = Normalized(target - position);
    if (MagnitudeSq(forward) == 0.0f) forward = vec3(0, 0, 1);  // eye == target: look along +Z
    vec3 right = Normalized(Cross(up, forward));
    if (MagnitudeSq(right) == 0.0f) {
        // up parallel to forward: pick any axis not parallel to forward.
        const vec3 alt = std::fabs(forward.x) < 0.9f ? vec3(1, 0, 0) : vec3(0, 0, 1);
        right = Normalized(Cross(alt, forward));
    }
    const vec3 newUp = Cross(forward, right);
    return mat4(right.x, newUp.x, forward.x, 0,  //
                right.y, newUp.y, forward.y, 0,  //
                right.z, newUp.z, forward.z, 0,  //
                -Dot(right, position), -Dot(newUp, position), -Dot(forward, position), 1);
}

mat4 Projection(float fov, float aspect, float zNear, float zFar) {
    const float tanHalfFov = std::tan(DEG2RAD(fov * 0.5f));
    const float fovY = 1.0f / tanHalfFov;
    const float fovX = fovY / aspect;
    mat4 r = ZeroMat4();
    r[0][0] = fovX;
    r[1][1] = fovY;
    r[2][2] = zFar / (zFar - zNear);
    r[2][3] = 1.0f;
    r[3][2] = -zNear * r[2][2];
    return r;
}

mat4 Ortho(float left, float right, float bottom, float top, float zNear, float zFar) {
    const float _11 = 2.0f / (right - left);
    const float _22 = 2.0f / (top - bottom);
    const float _33 = 1.0f / (zFar - zNear);
    const float _41 = (left + right) / (left - right);
    const float _42 = (top + bottom) / (bottom - top);
    const float _43 = zNear / (zNear - zFar);
    return mat4(_11, 0, 0, 0, 0, _22, 0, 0, 0, 0, _33, 0, _41, _42, _43, 1);
}

mat3 FastInverse(const mat3& mat) { return Transpose(mat); }

mat4 FastInverse(const mat4& mat) {
    mat4 inverse = Transpose(mat);
    inverse[3][0] = inverse[0][3] = 0.0f;
    inverse[3][1] = inverse[1][3] = 0.0f;
    inverse[3][2] = inverse[2][3] = 0.0f;
    const vec3 right(mat[0][0], mat[0][1], mat[0][2]);
    const vec3 up(mat[1][0], mat[1][1], mat[1][2]);
    const vec3 forward(mat[2][0], mat[2][1], mat[2][2]);
    const vec3 position(mat[3][0], mat[3][1], mat[3][2]);
    inverse[3][0] = -Dot(right, position);
    inverse[3][1] = -Dot(up, position);
    inverse[3][2] = -Dot(forward, position);
    return inverse;
}

mat3 Orthogonalize(const mat3& mat) {
    const vec3 xAxis(mat[0][0], mat[0][1], mat[0][2]);
    const vec3 yAxis(mat[1][0], mat[1][1], mat[1][2]);
    const vec3 zAxis = Normalized(Cross(xAxis, yAxis));
    const vec3 x = Normalized(Cross(yAxis, zAxis));
    const vec3 y = Cross(zAxis, x);
    return mat3(x.x, x.y, x.z, y.x, y.y, y.z, zAxis.x, zAxis.y, zAxis.z);
}

vec3 Decompose(const mat3& r) {
    // R = Z(roll) X(pitch) Y(yaw): row 3 is (cp*sy, -sp, cp*cy); R[0][1] = sr*cp, R[1][1] = cr*cp.
    const float sp = std::fmax(-1.0f, std::fmin(1.0f, -r[2][1]));
    const float pitch = std::asin(sp);
    const float yaw = std::atan2(r[2][0], r[2][2]);
    const float roll = std::atan2(r[0][1], r[1][1]);
    constexpr float toDeg = 180.0f / 3.14159265358979323846f;
    return {pitch * toDeg, yaw * toDeg, roll * toDeg};
}
