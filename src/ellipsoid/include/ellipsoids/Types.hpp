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

#include <cmath>
#include <limits>

namespace ellipsoids {

using Scalar = double;
using Vec3 = Eigen::Matrix<Scalar, 3, 1>;
using Mat3 = Eigen::Matrix<Scalar, 3, 3>;
using Quat = Eigen::Quaternion<Scalar>;
using Vec4 = Eigen::Matrix<Scalar, 4, 1>;
using Mat4 = Eigen::Matrix<Scalar, 4, 4>;

/// Machine epsilon of Scalar.
constexpr Scalar kEps = std::numeric_limits<Scalar>::epsilon();

}  // namespace ellipsoids

#endif
