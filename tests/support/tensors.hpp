#pragma once
/// 3-vectors and 3x3 matrices as the tests write them: the small algebra that expected values
/// are computed with, written here rather than taken from src/ so that a test does not share
/// the code it checks.
#include "mesh/mesh.hpp"

#include <array>
#include <cmath>

namespace kiln_test
{
using kiln::Point;
/// A 3x3 matrix, row by row.
using Matrix3 = std::array<std::array<double, 3>, 3>;

/// Voigt index of tensor component (i, j): xx, yy, zz, xy, xz, yz (Kiln's order).
inline constexpr int voigt_index[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
inline constexpr const char *voigt_name[6] = {"xx", "yy", "zz", "xy", "xz", "yz"};

inline double dot(const Point &a, const Point &b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline Point cross(const Point &a, const Point &b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline double norm(const Point &a)
{
  return std::sqrt(dot(a, a));
}

/// s v.
inline Point scaled(const double s, const Point &v)
{
  return {s * v[0], s * v[1], s * v[2]};
}

/// A x (not "apply": std::apply would win overload resolution for std::array arguments).
inline Point times(const Matrix3 &A, const Point &x)
{
  Point y{0, 0, 0};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      y[i] += A[i][k] * x[k];
  return y;
}

/// A B.
inline Matrix3 multiply(const Matrix3 &A, const Matrix3 &B)
{
  Matrix3 C{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        C[i][j] += A[i][k] * B[k][j];
  return C;
}

inline double determinant(const Matrix3 &m)
{
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

/// Column d of A (axis d of a rotated frame, in the global frame).
inline Point column(const Matrix3 &A, const int d)
{
  return {A[0][d], A[1][d], A[2][d]};
}

/// A diag(s) A^T: a tensor diagonal in the frame of A's columns.
inline Matrix3 rotated_diagonal(const Matrix3 &A, const Point &s)
{
  Matrix3 t{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        t[i][j] += A[i][k] * s[k] * A[j][k];
  return t;
}
} // namespace kiln_test
