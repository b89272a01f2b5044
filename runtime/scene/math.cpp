#include "scene/math.h"

#include <cmath>

namespace bake::play {

Mat4 identity() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 m{};
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      float sum = 0;
      for (int k = 0; k < 4; ++k) sum += a[k * 4 + r] * b[c * 4 + k];
      m[c * 4 + r] = sum;
    }
  }
  return m;
}

Mat4 lookAt(const Vec3& eye, const Vec3& target, const Vec3& up) {
  const Vec3 f = normalize(target - eye);
  Vec3 s = normalize(cross(f, up));
  if (length(s) == 0) s = normalize(cross(f, Vec3{0, 0, 1}));  // looking along the up axis
  const Vec3 u = cross(s, f);
  return {s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0,
          -dot(s, eye), -dot(u, eye), dot(f, eye), 1};
}

Mat4 perspective(float yfov, float aspect, float znear, float zfar) {
  const float f = 1.0f / std::tan(yfov / 2);
  Mat4 m{};
  m[0] = f / aspect;
  m[5] = f;
  m[10] = (zfar + znear) / (znear - zfar);
  m[11] = -1;
  m[14] = 2 * zfar * znear / (znear - zfar);
  return m;
}

Mat4 fromDoubles(const std::array<double, 16>& d) {
  Mat4 m{};
  for (int i = 0; i < 16; ++i) m[i] = float(d[i]);
  return m;
}

Vec3 transformPoint(const Mat4& m, const Vec3& p) {
  return {m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12], m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13],
          m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14]};
}

Mat3 normalMatrix(const Mat4& m) {
  // Cofactor matrix of the upper 3x3: the inverse transpose up to a scale, which shaders normalise away.
  const float a[3][3] = {{m[0], m[4], m[8]}, {m[1], m[5], m[9]}, {m[2], m[6], m[10]}};
  Mat3 out{};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      out[c * 3 + r] = a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1];
    }
  }
  float det = a[0][0] * out[0] + a[0][1] * out[3] + a[0][2] * out[6];
  if (det < 0) {  // mirrored transforms: keep normals pointing outwards
    for (float& v : out) v = -v;
  }
  return out;
}

Vec3 inverseTransformPoint(const Mat4& m, const Vec3& p) {
  const double a[3][3] = {{m[0], m[4], m[8]}, {m[1], m[5], m[9]}, {m[2], m[6], m[10]}};
  const double q[3] = {double(p[0]) - m[12], double(p[1]) - m[13], double(p[2]) - m[14]};
  double cofactor[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      cofactor[r][c] = a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1];
    }
  const double det = a[0][0] * cofactor[0][0] + a[0][1] * cofactor[0][1] + a[0][2] * cofactor[0][2];
  if (!(std::abs(det) > 0)) return p;
  Vec3 out{};
  for (int i = 0; i < 3; ++i)  // (A^-1)_ij = cofactor_ji / det
    out[std::size_t(i)] = float((cofactor[0][i] * q[0] + cofactor[1][i] * q[1] + cofactor[2][i] * q[2]) / det);
  return out;
}

}  // namespace bake::play
