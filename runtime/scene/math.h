// The little linear algebra a viewer needs: column-major 4x4 float matrices as OpenGL takes them,
// a look-at view, a perspective projection, and the normal matrix.
#pragma once

#include <array>
#include <cmath>

namespace bake::play {

using Vec3 = std::array<float, 3>;
using Mat4 = std::array<float, 16>;  // column-major
using Mat3 = std::array<float, 9>;   // column-major

inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 operator*(const Vec3& a, float s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline float dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline float length(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(const Vec3& a) {
  const float l = length(a);
  return l > 0 ? a * (1.0f / l) : Vec3{0, 0, 0};
}

Mat4 identity();
Mat4 multiply(const Mat4& a, const Mat4& b);
Mat4 lookAt(const Vec3& eye, const Vec3& target, const Vec3& up);
Mat4 perspective(float yfovRadians, float aspect, float znear, float zfar);
Mat4 fromDoubles(const std::array<double, 16>& m);
Vec3 transformPoint(const Mat4& m, const Vec3& p);
// The point that m maps to p (m affine and invertible; p itself when m is singular).
Vec3 inverseTransformPoint(const Mat4& m, const Vec3& p);
// Inverse transpose of the upper 3x3 (for normals).
Mat3 normalMatrix(const Mat4& m);

}  // namespace bake::play
