#pragma once
// vec2 / vec3 with the book's conventions (row vectors, left-handed, degrees in every rotation helper).
// Written as plain structs (no anonymous unions); operator[] indexes the components.

struct vec2 {
    float x = 0.0f, y = 0.0f;
    constexpr vec2() = default;
    constexpr vec2(float x_, float y_) : x(x_), y(y_) {}
    float& operator[](int i) { return i == 0 ? x : y; }
    float operator[](int i) const { return i == 0 ? x : y; }
};

struct vec3 {
    float x = 0.0f, y = 0.0f, z = 0.0f;
    constexpr vec3() = default;
    constexpr vec3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
    float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

vec2 operator+(const vec2& l, const vec2& r);
vec2 operator-(const vec2& l, const vec2& r);
vec2 operator*(const vec2& l, const vec2& r);
vec2 operator*(const vec2& l, float r);
vec2 operator/(const vec2& l, const vec2& r);
vec2 operator/(const vec2& l, float r);
vec2 operator-(const vec2& v);
vec2& operator+=(vec2& l, const vec2& r);
vec2& operator-=(vec2& l, const vec2& r);  // erratum 5.2-31: the book subtracts r.y from x
vec2& operator*=(vec2& l, const vec2& r);
vec2& operator*=(vec2& l, float r);
vec2& operator/=(vec2& l, const vec2& r);
vec2& operator/=(vec2& l, float r);
/// Component-wise CMP (absolute 0.005), as the book's operator==.
bool operator==(const vec2& l, const vec2& r);
bool operator!=(const vec2& l, const vec2& r);

inline vec3 operator+(const vec3& l, const vec3& r) { return {l.x + r.x, l.y + r.y, l.z + r.z}; }
inline vec3 operator-(const vec3& l, const vec3& r) { return {l.x - r.x, l.y - r.y, l.z - r.z}; }
inline vec3 operator*(const vec3& l, const vec3& r) { return {l.x * r.x, l.y * r.y, l.z * r.z}; }
inline vec3 operator*(const vec3& l, float r) { return {l.x * r, l.y * r, l.z * r}; }
inline vec3 operator*(float l, const vec3& r) { return {r.x * l, r.y * l, r.z * l}; }
inline vec3 operator/(const vec3& l, const vec3& r) { return {l.x / r.x, l.y / r.y, l.z / r.z}; }
inline vec3 operator/(const vec3& l, float r) { return {l.x / r, l.y / r, l.z / r}; }
inline vec3 operator-(const vec3& v) { return {-v.x, -v.y, -v.z}; }
inline vec3& operator+=(vec3& l, const vec3& r) { return l = l + r; }
inline vec3& operator-=(vec3& l, const vec3& r) { return l = l - r; }
inline vec3& operator*=(vec3& l, const vec3& r) { return l = l * r; }
inline vec3& operator*=(vec3& l, float r) { return l = l * r; }
inline vec3& operator/=(vec3& l, const vec3& r) { return l = l / r; }
inline vec3& operator/=(vec3& l, float r) { return l = l / r; }
bool operator==(const vec3& l, const vec3& r);
bool operator!=(const vec3& l, const vec3& r);

float Dot(const vec2& l, const vec2& r);
inline float Dot(const vec3& l, const vec3& r) { return l.x * r.x + l.y * r.y + l.z * r.z; }
float Magnitude(const vec2& v);
float Magnitude(const vec3& v);
float MagnitudeSq(const vec2& v);
inline float MagnitudeSq(const vec3& v) { return v.x * v.x + v.y * v.y + v.z * v.z; }
float Distance(const vec2& p1, const vec2& p2);
float Distance(const vec3& p1, const vec3& p2);
float DistanceSq(const vec2& p1, const vec2& p2);
float DistanceSq(const vec3& p1, const vec3& p2);
/// Scales v to unit length in place. A zero (or non-finite-length) vector is left unchanged (erratum 5.2-6).
void Normalize(vec2& v);
void Normalize(vec3& v);
/// Unit vector along v; the zero vector for a zero input, never NaN (erratum 5.2-6).
vec2 Normalized(const vec2& v);
vec3 Normalized(const vec3& v);
/// Left-handed cross product (same formula as right-handed; handedness shows in how it is drawn).
inline vec3 Cross(const vec3& l, const vec3& r) {
    return {l.y * r.z - l.z * r.y, l.z * r.x - l.x * r.z, l.x * r.y - l.y * r.x};
}
/// Angle between two vectors in radians; 0 if either is zero.
float Angle(const vec2& l, const vec2& r);
float Angle(const vec3& l, const vec3& r);
/// Projection of `length` onto `direction` (direction need not be unit; zero direction gives zero).
vec2 Project(const vec2& length, const vec2& direction);
vec3 Project(const vec3& length, const vec3& direction);
vec2 Perpendicular(const vec2& len, const vec2& dir);
vec3 Perpendicular(const vec3& len, const vec3& dir);
/// Reflects sourceVector about `normal` (unit).
vec2 Reflection(const vec2& sourceVector, const vec2& normal);
vec3 Reflection(const vec3& sourceVector, const vec3& normal);
/// Rotates a 2D vector by `degrees` (counter-clockwise for +degrees in a y-up frame).
vec2 RotateVector(const vec2& vector, float degrees);

/// Wraps degrees into [-360, 360] the way the book does (fmod, keeping sign).
float CorrectDegrees(float degrees);
/// Degrees to radians (pi/180) after wrapping to [-360, 360].
float DEG2RAD(float degrees);
/// Radians to degrees with the exact 180/pi (erratum 5.2-33: the book uses 57.295754), wrapped to [-360, 360].
float RAD2DEG(float radians);

/// True if every component is finite.
bool IsFinite(const vec3& v);
