/**
 * @file RigidBody.hpp
 * @brief A rigid ellipsoid in vacuum and its time step: the same scheme as the
 *        OpenFOAM library's free motion (bodyMotions::free), for the dry
 *        collision tests and validation without a flow.
 *
 * Translation: U1 = U0 + F dt/m, x1 = x0 + (U0 + U1) dt/2 (F held over the
 * step). Rotation: angular momentum L1 = L0 + T dt; attitude by a midpoint
 * quaternion step with omega at the half step from L0 + T dt/2 and the
 * world inertia there; omega1 = I(q1)^-1 L1 (gyroscopic term included).
 */
#ifndef COLLISION_RIGIDBODY_HPP
#define COLLISION_RIGIDBODY_HPP

#include "collision/CollisionModel.hpp"

namespace collision {

struct RigidBody {
  Vec3 semiAxes = Vec3::Ones();
  Vec3 centre = Vec3::Zero();
  Quat orientation = Quat::Identity();
  Vec3 velocity = Vec3::Zero();
  Vec3 angularVelocity = Vec3::Zero();  ///< world frame
  Scalar density = 1;
  bool movable = true;

  Scalar volume() const;
  Scalar mass() const { return density * volume(); }
  /// principal moments m (b^2 + c^2)/5, ... in the body frame
  Vec3 bodyInertia() const;
  Mat3 worldInertia(const Quat& q) const;
  Vec3 linearMomentum() const { return mass() * velocity; }
  /// about the origin: x ^ m U + I omega
  Vec3 angularMomentum() const;
  Scalar kineticEnergy() const;

  CollisionBody collisionBody() const;

  /// One step of length dt under the force F and torque T (about the centre).
  void advance(const Vec3& force, const Vec3& torque, Scalar dt);
};

/**
 * One Heun sub-step of bodies in vacuum under their collision forces (the
 * scheme the OpenFOAM library uses, see CollisionModel.hpp).
 */
void collisionSubStep(std::vector<RigidBody>& bodies, CollisionModel& model, Scalar contactTime,
                      Scalar dt);

/// A fluid-free step dt in the sub-steps the model asks for; returns their number.
int collisionStep(std::vector<RigidBody>& bodies, CollisionModel& model, Scalar contactTime,
                  Scalar dt);

}  // namespace collision

#endif
