#include "collision/RigidBodyStep.hpp"

#include <cmath>
#include <limits>

namespace collision {

Scalar ellipsoidVolume(const Vec3& semiAxes) { return 4 * kPi / 3 * semiAxes.prod(); }

Vec3 ellipsoidInertia(const Vec3& semiAxes, Scalar mass) {
  const Vec3 s = semiAxes.cwiseAbs2();
  return mass / 5 * Vec3(s.y() + s.z(), s.x() + s.z(), s.x() + s.y());
}

Mat3 worldInertia(const Quat& q, const Vec3& principalInertia) {
  const Mat3 R = q.toRotationMatrix();
  return R * principalInertia.asDiagonal() * R.transpose();
}

Mat3 inverseWorldInertia(const Quat& q, const Vec3& principalInertia) {
  const Mat3 R = q.toRotationMatrix();
  return R * principalInertia.cwiseInverse().asDiagonal() * R.transpose();
}

Quat rotationQuaternion(const Vec3& w) {
  const Scalar angle = w.norm();
  if (!(angle > std::numeric_limits<Scalar>::min())) return Quat::Identity();
  return Quat(Eigen::AngleAxis<Scalar>(angle, w / angle));
}

void advanceRigidBody(BodyState& s, Scalar dt, const Vec3& impulse, const Vec3& angularImpulse,
                      Scalar mass, const Vec3& principalInertia, bool translates, bool rotates) {
  if (translates) {
    const Vec3 u1 = s.velocity + impulse / mass;
    s.centre += 0.5 * dt * (s.velocity + u1);
    s.velocity = u1;
  } else {
    s.velocity.setZero();
  }

  if (rotates) {
    const Quat q0 = s.orientation;
    const Vec3 l0 = worldInertia(q0, principalInertia) * s.angularVelocity;
    const Vec3 l1 = l0 + angularImpulse;
    // the attitude at the middle of the step with the old angular velocity
    const Quat half = (rotationQuaternion(0.5 * dt * s.angularVelocity) * q0).normalized();
    const Vec3 omegaHalf = inverseWorldInertia(half, principalInertia) * (l0 + 0.5 * angularImpulse);
    s.orientation = (rotationQuaternion(dt * omegaHalf) * q0).normalized();
    s.angularVelocity = inverseWorldInertia(s.orientation, principalInertia) * l1;
  } else {
    s.angularVelocity.setZero();
  }
}

}  // namespace collision
