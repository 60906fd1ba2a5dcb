/**
 * @file Types.hpp
 * @brief Scalar and vector types of the geometry core (one place to change them).
 *
 * Pure C++17 + Eigen: the geometry core never includes OpenFOAM.
 */
#ifndef ELLIPSOIDS_TYPES_HPP
#define ELLIPSOIDS_TYPES_HPP

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <limits>

// The layout of Eigen's fixed-size types depends on the instruction set it is
// compiled for (AVX aligns them to 32 bytes, SSE to 16) unless their alignment
// is capped. The core is compiled for the native CPU while OpenFOAM code that
// uses it is not: every translation unit that sees these types must agree, so
// the cap is part of the interface (set by CMake for its targets and by
// etc/wmake/options for OpenFOAM code).
#if !defined(EIGEN_MAX_ALIGN_BYTES) || EIGEN_MAX_ALIGN_BYTES != 16
#error "Compile with -DEIGEN_MAX_ALIGN_BYTES=16 (see ellipsoids/Types.hpp): the geometry core's types must have one layout"
#endif

namespace ellipsoids {

using Scalar = double;
using Vec3 = Eigen::Matrix<Scalar, 3, 1>;
using Mat3 = Eigen::Matrix<Scalar, 3, 3>;
using Quat = Eigen::Quaternion<Scalar>;
using Vec4 = Eigen::Matrix<Scalar, 4, 1>;
using Mat4 = Eigen::Matrix<Scalar, 4, 4>;
/// A third-order tensor T_ijk, stored as T[k](i, j).
using Tensor3 = std::array<Mat3, 3>;

/// Machine epsilon of Scalar.
constexpr Scalar kEps = std::numeric_limits<Scalar>::epsilon();

/// pi, for every layer above the geometry core too.
constexpr Scalar kPi = 3.14159265358979323846;

}  // namespace ellipsoids

#endif
