/**
 * @file Friction.hpp
 * @brief The tangential force of a contact: the interface of the friction
 *        laws a pair or wall model combines with its normal contact.
 *
 * Implementations: NoFriction, CoulombFriction (sliding only),
 * SpringCoulombFriction (a tangential spring bounded by Coulomb's limit:
 * static and sliding friction). The models that use them:
 * PairModel, WallModel; the laws and their constants: docs/collisions.md.
 */
#ifndef COLLISION_FRICTION_HPP
#define COLLISION_FRICTION_HPP

#include "collision/ContactLaw.hpp"
#include "collision/SpringDashpotContact.hpp"

namespace collision {

class Friction {
 public:
  virtual ~Friction() = default;

  /**
   * Add the tangential force on body 2 (body 1 gets minus it) to force.
   * @param normalForce the normal force on body 2 along n (its magnitude bounds the friction)
   * @param n unit normal from 1 to 2
   * @param relativeVelocity (v_2 - v_1) at the contact point
   * @param dt the sub-step the force is held over
   * @param elapsed the time since the contact's last call (0 at its first)
   * @param contact the contact's state (its contact time; the tangential
   *        spring, which a law with one advances over elapsed)
   */
  virtual void addForce(Scalar normalForce, const Vec3& n, const Vec3& relativeVelocity,
                        const ContactSide& s1, const ContactSide& s2, Scalar dt, Scalar elapsed,
                        ContactState& contact, Vec3& force) const = 0;
};

}  // namespace collision

#endif
