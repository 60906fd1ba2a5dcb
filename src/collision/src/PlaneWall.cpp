#include "collision/PlaneWall.hpp"

#include <cmath>
#include <stdexcept>

namespace collision {

void PlaneWall::validate() const {
  if (!point.allFinite() || !normal.allFinite() || std::abs(normal.norm() - 1) > 1e-9) {
    throw std::invalid_argument("wall '" + name +
                                "': the point must be finite and the normal a unit vector");
  }
}

WallDistance wallDistance(const ellipsoids::Ellipsoid& body, const PlaneWall& wall) {
  const Vec3 Pn = body.shapeMatrix() * wall.normal;
  const Scalar h = std::sqrt(wall.normal.dot(Pn));
  WallDistance w;
  w.distance = wall.normal.dot(body.centre() - wall.point) - h;
  w.bodyPoint = body.centre() - Pn / h;
  w.wallPoint = w.bodyPoint - w.distance * wall.normal;
  return w;
}

}  // namespace collision
