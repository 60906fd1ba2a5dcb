#include "collision/CoulombFriction.hpp"

#include <algorithm>
#include <cmath>

namespace collision {

void CoulombFriction::addForce(Scalar normalForce, const Vec3& n, const Vec3& relativeVelocity,
                               const ContactSide& s1, const ContactSide& s2, Scalar dt, Scalar,
                               ContactState&, Vec3& force) const {
  if (!(coefficient_ > 0)) return;
  const Scalar un = relativeVelocity.dot(n);
  const Vec3 ut = relativeVelocity - un * n;
  const Scalar slip = ut.norm();
  if (!(slip > 0)) return;
  const Vec3 t = ut / slip;
  const Scalar wt = inverseEffectiveMass(s1, s2, t);
  const Scalar stop = wt > 0 ? slip / (wt * dt) : 0;
  // on body 2 the friction opposes its slip relative to body 1
  force -= std::min(coefficient_ * std::abs(normalForce), stop) * t;
}

}  // namespace collision
