/**
 * @file RigidBodySet.hpp
 * @brief The BodySet of rigid bodies in vacuum: their collision forces are
 *        their only forces.
 */
#ifndef COLLISION_RIGIDBODYSET_HPP
#define COLLISION_RIGIDBODYSET_HPP

#include "collision/BodySet.hpp"
#include "collision/RigidBody.hpp"

#include <vector>

namespace collision {

class RigidBodySet : public BodySet {
 public:
  /// The set of bodies (their shapes, densities, mobility; the states are the stepper's).
  explicit RigidBodySet(const std::vector<RigidBody>& bodies) : bodies_(bodies) {}

  std::size_t size() const override { return bodies_.size(); }
  CollisionBody collisionBody(std::size_t i, const BodyState& s) const override;
  /// advanceRigidBody under the collision force alone (an immovable body stays)
  void advance(std::size_t i, BodyState& s, Scalar t, Scalar dt, const Vec3& fc,
               const Vec3& tc) const override;

 private:
  const std::vector<RigidBody>& bodies_;
};

}  // namespace collision

#endif
