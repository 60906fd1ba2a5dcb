/**
 * @file Types.hpp
 * @brief Types of the collision core (pure C++17 + Eigen on the geometry core;
 *        never OpenFOAM).
 */
#ifndef COLLISION_TYPES_HPP
#define COLLISION_TYPES_HPP

#include "ellipsoids/Types.hpp"

namespace collision {

using ellipsoids::kPi;
using ellipsoids::Mat3;
using ellipsoids::Quat;
using ellipsoids::Scalar;
using ellipsoids::Tensor3;
using ellipsoids::Vec3;

}  // namespace collision

#endif
