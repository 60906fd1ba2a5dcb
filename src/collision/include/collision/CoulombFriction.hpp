/**
 * @file CoulombFriction.hpp
 * @brief Regularised Coulomb sliding friction.
 *
 * F_t = -min(mu |F_n|, m_t |u_t|/dt) t on body 2, t = u_t/|u_t| the slip
 * direction at the contact point and m_t its effective mass along t: Coulomb
 * sliding friction that at most stops the slip within the sub-step dt (no
 * tangential spring: sticking is not held against a steady load).
 *
 * Usage: frictionModel coulombSliding; the coefficient mu is
 * ContactParameters::friction, in ContactParameters::kFrictionRange (default
 * 0: no force).
 *
 * See also: Friction, NoFriction, SpringCoulombFriction, PairModel, WallModel.
 */
#ifndef COLLISION_COULOMBFRICTION_HPP
#define COLLISION_COULOMBFRICTION_HPP

#include "collision/Friction.hpp"

namespace collision {

class CoulombFriction : public Friction {
 public:
  /// @param coefficient mu >= 0 (0: no force)
  explicit CoulombFriction(Scalar coefficient) : coefficient_(coefficient) {}

  Scalar coefficient() const { return coefficient_; }

  void addForce(Scalar normalForce, const Vec3& n, const Vec3& relativeVelocity,
                const ContactSide& s1, const ContactSide& s2, Scalar dt, Scalar elapsed,
                ContactState& contact, Vec3& force) const override;

 private:
  Scalar coefficient_ = 0;
};

}  // namespace collision

#endif
