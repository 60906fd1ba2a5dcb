/**
 * @file NoFriction.hpp
 * @brief Frictionless contact: no tangential force.
 *
 * See also: Friction, CoulombFriction.
 */
#ifndef COLLISION_NOFRICTION_HPP
#define COLLISION_NOFRICTION_HPP

#include "collision/Friction.hpp"

namespace collision {

class NoFriction : public Friction {
 public:
  void addForce(Scalar, const Vec3&, const Vec3&, const ContactSide&, const ContactSide&, Scalar,
                Scalar, ContactState&, Vec3&) const override {}
};

}  // namespace collision

#endif
