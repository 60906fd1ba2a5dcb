#include "collision/RollingResistance.hpp"

#include <algorithm>
#include <cmath>

namespace collision {

Vec3 rollingResistanceTorque(Scalar coefficient, Scalar rollingRadius, Scalar normalForce, const Vec3& n,
                             const Vec3& omega1, const Vec3& omega2, const ContactSide& s1,
                             const ContactSide& s2, Scalar dt) {
  if (!(coefficient > 0)) return Vec3::Zero();
  Vec3 rolling = omega1 - omega2;
  rolling -= rolling.dot(n) * n;
  const Scalar rate = rolling.norm();
  if (!(rate > 0)) return Vec3::Zero();
  const Vec3 e = rolling / rate;
  Scalar wr = 0;
  for (const ContactSide* s : {&s1, &s2}) {
    if (s->movable) wr += e.dot(s->inverseInertia * e);
  }
  if (!(wr > 0)) return Vec3::Zero();
  const Scalar torque = std::min(coefficient * rollingRadius * std::abs(normalForce), rate / (wr * dt));
  return torque * e;  // on body 2: along omega_1 - omega_2, against body 1's rolling
}

}  // namespace collision
