#include "collision/SpringCoulombFriction.hpp"

#include <cmath>

namespace collision {

namespace {
/// v turned into the plane normal to the unit n, its length kept
Vec3 intoPlane(const Vec3& v, const Vec3& n) {
  const Vec3 projected = v - v.dot(n) * n;
  const Scalar length = projected.norm();
  return length > 0 ? Vec3(projected * (v.norm() / length)) : Vec3::Zero();
}
}  // namespace

void SpringCoulombFriction::addForce(Scalar normalForce, const Vec3& n, const Vec3& relativeVelocity,
                                     const ContactSide& s1, const ContactSide& s2, Scalar,
                                     Scalar elapsed, ContactState& contact, Vec3& force) const {
  const Vec3 ut = relativeVelocity - relativeVelocity.dot(n) * n;
  if (!(coefficient_ > 0)) {
    contact.tangentialSpring = Vec3::Zero();
    contact.tangentialSlip = ut;
    return;
  }
  // the spring and the last slip turned into the current tangent plane (their
  // lengths kept), then the slip of the time since the last call (trapezoidal)
  Vec3 xi = intoPlane(contact.tangentialSpring, n);
  xi += 0.5 * (intoPlane(contact.tangentialSlip, n) + ut) * elapsed;
  contact.tangentialSlip = ut;
  const Scalar xiNorm = xi.norm();
  const Scalar utNorm = ut.norm();
  if (!(xiNorm > 0) && !(utNorm > 0)) {
    contact.tangentialSpring = Vec3::Zero();
    return;
  }
  // the spring-dashpot of the contact's time and restitution for the
  // effective mass along the spring (or the slip, while the spring is empty)
  const Vec3 along = xiNorm > 0 ? Vec3(xi / xiNorm) : Vec3(ut / utNorm);
  const Scalar wt = inverseEffectiveMass(s1, s2, along);
  if (!(wt > 0) || !(contact.contactTime > 0)) {
    contact.tangentialSpring = Vec3::Zero();
    return;
  }
  const SpringDashpot law = springDashpot(1 / wt, restitution_, contact.contactTime);
  Vec3 ft = -law.stiffness * xi - law.damping * ut;
  const Scalar limit = coefficient_ * std::abs(normalForce);
  const Scalar magnitude = ft.norm();
  if (magnitude > limit) {
    // sliding: the Coulomb force along the trial force, and the elongation it stands for
    ft *= magnitude > 0 ? limit / magnitude : 0;
    xi = -(ft + law.damping * ut) / law.stiffness;
  }
  contact.tangentialSpring = xi;
  force += ft;
}

}  // namespace collision
