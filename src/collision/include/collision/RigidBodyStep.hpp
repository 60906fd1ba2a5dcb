/**
 * @file RigidBodyStep.hpp
 * @brief The state of a rigid ellipsoid, its mass properties and its time
 *        step: the one integrator of every free body, coupled or in vacuum.
 *
 * One step of length dt under an impulse J = F dt and an angular impulse
 * H = T dt (about the centre), both held over the step:
 *  - translation by the trapezoidal rule: U1 = U0 + J/m, x1 = x0 + (U0 + U1) dt/2;
 *  - rotation on the angular momentum L = I(q) omega: L1 = L0 + H; the
 *    attitude by a midpoint quaternion step, omega at the half step from
 *    L0 + H/2 and the world inertia at the attitude reached with the old
 *    omega; omega1 = I(q1)^-1 L1 (the gyroscopic term is included).
 * Both are second order in dt.
 */
#ifndef COLLISION_RIGIDBODYSTEP_HPP
#define COLLISION_RIGIDBODYSTEP_HPP

#include "collision/Types.hpp"

namespace collision {

/// Position, attitude and velocities of a rigid body (world frame).
struct BodyState {
  Vec3 centre = Vec3::Zero();
  /// rotation from the body frame to the world frame
  Quat orientation = Quat::Identity();
  Vec3 velocity = Vec3::Zero();
  Vec3 angularVelocity = Vec3::Zero();

  /// the rigid-body velocity at the point x
  Vec3 velocityAt(const Vec3& x) const { return velocity + angularVelocity.cross(x - centre); }
};

/// 4/3 pi a b c
Scalar ellipsoidVolume(const Vec3& semiAxes);

/// Principal moments of inertia of a homogeneous ellipsoid: m (b^2 + c^2)/5, ...
Vec3 ellipsoidInertia(const Vec3& semiAxes, Scalar mass);

/// R(q) diag(I) R(q)^T
Mat3 worldInertia(const Quat& q, const Vec3& principalInertia);

/// R(q) diag(1/I) R(q)^T
Mat3 inverseWorldInertia(const Quat& q, const Vec3& principalInertia);

/// The rotation by the angle |w| about w/|w| (identity for w = 0).
Quat rotationQuaternion(const Vec3& w);

/**
 * Advance s over dt (see the file's description). A body that does not
 * translate (rotate) has its velocity (angular velocity) set to zero.
 */
void advanceRigidBody(BodyState& s, Scalar dt, const Vec3& impulse, const Vec3& angularImpulse,
                      Scalar mass, const Vec3& principalInertia, bool translates = true,
                      bool rotates = true);

}  // namespace collision

#endif
