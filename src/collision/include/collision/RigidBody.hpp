/**
 * @file RigidBody.hpp
 * @brief A rigid ellipsoid in vacuum (the dry collision tests and
 *        validation/dryCollisions) and its steps through the one collision
 *        sub-step (SubStepper) and rigid-body integrator (RigidBodyStep)
 *        that coupled runs use.
 */
#ifndef COLLISION_RIGIDBODY_HPP
#define COLLISION_RIGIDBODY_HPP

#include "collision/CollisionModel.hpp"
#include "collision/RigidBodyStep.hpp"

#include <vector>

namespace collision {

struct RigidBody : BodyState {
  Vec3 semiAxes = Vec3::Ones();
  Scalar density = 1;
  bool movable = true;

  Scalar volume() const { return ellipsoidVolume(semiAxes); }
  Scalar mass() const { return density * volume(); }
  /// principal moments m (b^2 + c^2)/5, ... in the body frame
  Vec3 bodyInertia() const { return ellipsoidInertia(semiAxes, mass()); }
  Mat3 worldInertia(const Quat& q) const { return collision::worldInertia(q, bodyInertia()); }
  Vec3 linearMomentum() const { return mass() * velocity; }
  /// about the origin: x ^ m U + I omega
  Vec3 angularMomentum() const;
  Scalar kineticEnergy() const;

  /// The body at the state s as the collision model sees it.
  CollisionBody collisionBody(const BodyState& s) const;
  /// The body at its own state as the collision model sees it.
  CollisionBody collisionBody() const { return collisionBody(*this); }
};

/// One sub-step dt of bodies in vacuum under their collision forces (SubStepper).
void collisionSubStep(std::vector<RigidBody>& bodies, CollisionModel& model, Scalar contactTime,
                      Scalar dt);

/// A fluid-free step dt in the sub-steps the model asks for; returns their number.
int collisionStep(std::vector<RigidBody>& bodies, CollisionModel& model, Scalar contactTime,
                  Scalar dt);

}  // namespace collision

#endif
