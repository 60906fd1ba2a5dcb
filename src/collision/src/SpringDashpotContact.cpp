#include "collision/SpringDashpotContact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace collision {

SpringDashpotContact::SpringDashpotContact(Scalar restitution, Scalar sustainedLoadOverlap)
    : restitution_(restitution), sustainedLoadOverlap_(sustainedLoadOverlap) {
  ContactParameters p;
  p.restitution = restitution;
  p.sustainedLoadOverlap = sustainedLoadOverlap;
  p.validate();
}

ContactState SpringDashpotContact::firstTouch(Scalar contactTime, Scalar un, Scalar cap) const {
  ContactState c;
  c.contactTime = contactTime;
  if (un < 0) c.contactTime = std::min(c.contactTime, kPi * cap / -un);
  return c;
}

Scalar SpringDashpotContact::force(ContactState& c, Scalar overlap, Scalar un, Scalar inverseMass,
                                   Scalar cap, Scalar load, long& stiffened) const {
  const Scalar e = restitution_;
  SpringDashpot law;
  if (c.stiffness > 0) {
    // the spring-dashpot of the first touch (a fixed linear oscillator)
    law = springDashpotOfStiffness(c.stiffness, e, c.contactTime);
    c.springForce = std::max(Scalar(0), c.springForce + law.stiffness * (overlap - c.overlap));
  } else {
    law = springDashpot(1 / inverseMass, e, c.contactTime);  // the first touch (or an old restart)
    c.springForce = law.stiffness * overlap;
  }
  // still approaching faster than the contact time was made for (a body
  // swinging into the contact): the first touch's rule at the new speed,
  // for the overlap still allowed (at least half the cap); dF = k d(delta)
  // keeps the stiffer spring from returning more work than it took
  const Scalar left = std::max(cap - overlap, Scalar(0.5) * cap);
  if (un < 0 && kPi * cap < -un * c.contactTime && kPi * left < -un * c.contactTime) {
    const Scalar shorter = kPi * left / -un;
    const Scalar ratio = c.contactTime / shorter;
    law.stiffness *= ratio * ratio;
    law.damping *= ratio;
    c.contactTime = shorter;
    ++stiffened;
  }
  // a sustained load (gravity, the flow, bodies above): a spring made for an
  // impact's contact time can be far too soft to carry it. The spring is
  // stiffened so that the load overlaps it by at most the fraction f of the
  // cap: k >= W/(f cap); the spring of an impact without a load is left alone
  if (load > 0) {
    const Scalar needed = load / (sustainedLoadOverlap_ * cap);
    if (needed > law.stiffness) {
      const Scalar ratio = std::sqrt(needed / law.stiffness);
      law.stiffness = needed;
      law.damping *= ratio;
      c.contactTime /= ratio;
      ++stiffened;
    }
  }
  c.stiffness = law.stiffness;
  c.overlap = overlap;
  return normalForce(c.springForce, un, law);
}

}  // namespace collision
