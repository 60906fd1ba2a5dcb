/**
 * @file SpringCoulombFriction.hpp
 * @brief Tangential spring-dashpot bounded by Coulomb's limit: static and
 *        sliding friction (Cundall & Strack 1979; the projection of the
 *        spring onto the turning tangent plane and its reset on sliding as in
 *        Luding 2008).
 *
 * The contact carries the spring's elongation xi (ContactState::
 * tangentialSpring, zero at the first touch, kept through restarts) and the
 * slip velocity of its last call. Each call turns both into the current
 * tangent plane (keeping their lengths) and adds the slip over the time
 * elapsed since the last call by the trapezoidal rule, (u_last + u_t)/2
 * elapsed (u_t the tangential velocity of body 2 relative to body 1 at the
 * contact point: zero for bodies rolling on each other): the sub-stepper's
 * predictor, at the time of the last corrector, adds nothing and its
 * corrector the whole sub-step. Body 2 gets
 *     F_t = -k_t xi - eta_t u_t,   |F_t| <= mu |F_n|;
 * at the limit F_t is scaled to mu |F_n| and xi set to -(F_t + eta_t u_t)/k_t,
 * the elongation that force stands for (sliding). k_t and eta_t are the
 * spring-dashpot of the contact's own time T_c and restitution e for the
 * effective mass m_t of the contact point along the spring (ContactLaw.hpp:
 * the rotation included), so that the tangential oscillation has the normal
 * one's period and damping: for two spheres k_t = (2/7) k_n, and a sticking
 * impact leaves with the contact point's tangential velocity reversed, -e
 * times (Maw, Barber & Fawcett 1976 for the elastic case). A load below
 * mu |F_n| is held by an elongation F/k_t: the contact does not creep.
 *
 * Usage: frictionModel coulombSpring (the default); mu is
 * ContactParameters::friction (0: no force and no spring).
 *
 * See also: Friction, CoulombFriction (sliding only), docs/collisions.md.
 */
#ifndef COLLISION_SPRINGCOULOMBFRICTION_HPP
#define COLLISION_SPRINGCOULOMBFRICTION_HPP

#include "collision/Friction.hpp"

namespace collision {

class SpringCoulombFriction : public Friction {
 public:
  /// @param coefficient mu >= 0 (0: no force); restitution e of the contact, in (0, 1]
  SpringCoulombFriction(Scalar coefficient, Scalar restitution)
      : coefficient_(coefficient), restitution_(restitution) {}

  Scalar coefficient() const { return coefficient_; }

  void addForce(Scalar normalForce, const Vec3& n, const Vec3& relativeVelocity,
                const ContactSide& s1, const ContactSide& s2, Scalar dt, Scalar elapsed,
                ContactState& contact, Vec3& force) const override;

 private:
  Scalar coefficient_ = 0;
  Scalar restitution_ = 1;
};

}  // namespace collision

#endif
