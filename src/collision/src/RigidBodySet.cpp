#include "collision/RigidBodySet.hpp"

namespace collision {

CollisionBody RigidBodySet::collisionBody(std::size_t i, const BodyState& s) const {
  return bodies_[i].collisionBody(s);
}

void RigidBodySet::advance(std::size_t i, BodyState& s, Scalar, Scalar dt, const Vec3& fc,
                           const Vec3& tc) const {
  const RigidBody& body = bodies_[i];
  if (!body.movable) return;
  advanceRigidBody(s, dt, fc * dt, tc * dt, body.mass(), body.bodyInertia());
}

}  // namespace collision
