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

Scalar SpringDashpotContact::force(ContactState& c, const ContactLoading& l,
                                   long& stiffened) const {
  const Scalar e = restitution_;
  const Scalar overlap = l.overlap, un = l.normalSpeed, cap = l.cap;
  SpringDashpot law;
  if (c.stiffness > 0) {
    // the spring-dashpot of the first touch (a fixed linear oscillator)
    law = springDashpotOfStiffness(c.stiffness, e, c.contactTime);
    c.springForce = std::max(Scalar(0), c.springForce + law.stiffness * (overlap - c.overlap));
  } else {
    law = springDashpot(1 / l.inverseMass, e, c.contactTime);  // the first touch (or an old restart)
    c.springForce = law.stiffness * overlap;
  }
  // stiffen to k (never softer): the contact time shrinks as 1/sqrt(k) and
  // the dashpot grows as sqrt(k), so that the pair still rebounds with e;
  // dF = k d(delta) keeps the stiffer spring from returning more work than it took
  auto stiffenTo = [&](Scalar k) {
    if (!(k > law.stiffness)) return;
    const Scalar ratio = std::sqrt(k / law.stiffness);
    law.stiffness = k;
    law.damping *= ratio;
    c.contactTime /= ratio;
    ++stiffened;
  };
  // an approaching contact must take up the approach's kinetic energy and
  // the load's work within the overlap still allowed D: F D + k D^2/2 >=
  // m_eff u_n^2/2 + W D. An impact at the speed its spring was made for
  // meets it (the oscillator of T_c <= pi cap/u_n keeps it while it closes)
  // but for the overlap its first evaluation finds inside a sub-step, which
  // a fast capped impact makes up here; a body that swings into the contact
  // does not, nor does a contact loaded by another one's impact (a body
  // stopped by a wall while the one behind it comes on): the spring is
  // stiffened to meet it, at most as stiff as the sub-step resolves: the
  // contact's oscillation with the current m_eff, and the contact's own T_c
  // (kept for the mass of its first touch; the island's sub-steps follow
  // it), last no less than the shortest contact time. A spring stiffened to
  // it needs no more sub-steps in the next step whatever m_eff has become
  // since the first touch (a turning spheroid moves its contact point).
  // Beyond the cap (D <= 0) no spring meets the check: the spring is left as
  // it is (the load rule below still acts), since stiffening it there, at
  // every evaluation, to a shortest contact time that other contacts shorten
  // would shrink the island's sub-steps step after step
  if (un < 0) {
    const Scalar approachEnergy = 0.5 * un * un / l.inverseMass;
    const Scalar left = cap - overlap;
    const Scalar taken = c.springForce * left + 0.5 * law.stiffness * left * left;
    if (left > 0 && approachEnergy + l.load * left > taken) {
      const Scalar lnE = std::log(e);
      const Scalar shortest = l.shortestContactTime;
      const Scalar timeRatio = c.contactTime / shortest;
      const Scalar resolved =
          std::min((kPi * kPi + lnE * lnE) / (l.inverseMass * shortest * shortest),
                   law.stiffness * timeRatio * timeRatio);
      const Scalar needed =
          2 * (approachEnergy + (l.load - c.springForce) * left) / (left * left);
      stiffenTo(std::min(needed, resolved));
    }
  }
  // a sustained load (gravity, the flow, bodies above): a spring made for an
  // impact's contact time can be far too soft to carry it. The spring is
  // stiffened so that the load overlaps it by at most the fraction f of the
  // cap: k >= W/(f cap); the spring of an impact without a load is left alone
  if (l.load > 0) stiffenTo(l.load / (sustainedLoadOverlap_ * cap));
  c.stiffness = law.stiffness;
  c.overlap = overlap;
  return normalForce(c.springForce, un, law);
}

}  // namespace collision
