#include "collision/ContactLaw.hpp"
#include "collision/CoulombFriction.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace collision {

void ContactParameters::validate() const {
  if (!kRestitutionRange.contains(restitution)) {
    throw std::invalid_argument("contact: " +
                                outOfRangeMessage("restitution", restitution, kRestitutionRange));
  }
  if (!kFrictionRange.contains(friction)) {
    throw std::invalid_argument("contact: " +
                                outOfRangeMessage("friction", friction, kFrictionRange));
  }
  if (!kRollingFrictionRange.contains(rollingFriction)) {
    throw std::invalid_argument("contact: " + outOfRangeMessage("rollingFriction", rollingFriction,
                                                                kRollingFrictionRange));
  }
  if (!kSustainedLoadOverlapRange.contains(sustainedLoadOverlap)) {
    throw std::invalid_argument("contact: " + outOfRangeMessage("sustainedLoadOverlap",
                                                                sustainedLoadOverlap,
                                                                kSustainedLoadOverlapRange));
  }
  const auto& models = frictionModels();
  if (std::find(models.begin(), models.end(), frictionModel) == models.end()) {
    throw std::invalid_argument("contact: frictionModel '" + frictionModel +
                                "' unknown (allowed: coulombSpring, coulombSliding)");
  }
}

const std::vector<std::string>& ContactParameters::frictionModels() {
  static const std::vector<std::string> names{"coulombSpring", "coulombSliding"};
  return names;
}

Scalar inverseEffectiveMass(const ContactSide& s1, const ContactSide& s2, const Vec3& d) {
  Scalar w = 0;
  for (const ContactSide* s : {&s1, &s2}) {
    if (!s->movable) continue;
    const Vec3 rxd = s->arm.cross(d);
    w += s->inverseMass + rxd.dot(s->inverseInertia * rxd);
  }
  return w;
}

SpringDashpot springDashpot(Scalar effectiveMass, Scalar restitution, Scalar contactTime) {
  const Scalar lnE = std::log(restitution);
  SpringDashpot law;
  law.stiffness = effectiveMass * (kPi * kPi + lnE * lnE) / (contactTime * contactTime);
  law.damping = -2 * effectiveMass * lnE / contactTime;
  return law;
}

SpringDashpot springDashpotOfStiffness(Scalar stiffness, Scalar restitution, Scalar contactTime) {
  const Scalar lnE = std::log(restitution);
  SpringDashpot law;
  law.stiffness = stiffness;
  law.damping = -2 * lnE * stiffness * contactTime / (kPi * kPi + lnE * lnE);
  return law;
}

Scalar normalForce(Scalar elasticForce, Scalar normalSpeed, const SpringDashpot& law) {
  const Scalar fn = elasticForce - law.damping * normalSpeed;
  // the dashpot's tensile end belongs to the spring's unloading: once the
  // elastic force is spent (a stiffness that rose in the contact), no pull
  if (!(elasticForce > 0) && fn < 0) return 0;
  return fn;
}

Vec3 contactForce(Scalar elasticForce, const Vec3& n, const Vec3& relativeVelocity,
                  const SpringDashpot& law, const ContactSide& s1, const ContactSide& s2,
                  Scalar friction, Scalar dt) {
  const Scalar fn = normalForce(elasticForce, relativeVelocity.dot(n), law);
  Vec3 force = fn * n;
  ContactState state;
  CoulombFriction(friction).addForce(fn, n, relativeVelocity, s1, s2, dt, 0, state, force);
  return force;
}

}  // namespace collision
