/**
 * @file PlaneWall.hpp
 * @brief A fixed plane wall and its exact signed distance to an ellipsoid
 *        from the support function (no iteration).
 *
 * Wall {x : nw.(x - p) = 0}, nw the unit normal into the fluid. For an
 * ellipsoid (centre r, shape matrix P) the signed distance is
 *     d = nw.(r - p) - sqrt(nw^T P nw)
 * (negative: the overlap depth), reached at the body point
 * x_b = s(-nw) = r - P nw/sqrt(nw^T P nw) and the wall point x_b - d nw.
 */
#ifndef COLLISION_PLANEWALL_HPP
#define COLLISION_PLANEWALL_HPP

#include "collision/Types.hpp"
#include "ellipsoids/Ellipsoid.hpp"

#include <string>

namespace collision {

struct PlaneWall {
  std::string name;
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  ///< unit, into the fluid

  /// @throws std::invalid_argument on a non-finite point or a normal that is not unit
  void validate() const;
};

struct WallDistance {
  Scalar distance = 0;       ///< signed (negative: overlap)
  Vec3 bodyPoint = Vec3::Zero();
  Vec3 wallPoint = Vec3::Zero();
};

WallDistance wallDistance(const ellipsoids::Ellipsoid& body, const PlaneWall& wall);

}  // namespace collision

#endif
