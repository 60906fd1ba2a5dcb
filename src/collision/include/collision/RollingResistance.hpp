/**
 * @file RollingResistance.hpp
 * @brief Rolling friction of a contact: a torque against the bodies'
 *        relative rolling, bounded by mu_r R_r |F_n| (the constant directional
 *        torque of Ai, Chen, Rotter & Ooi 2011, model A).
 *
 * With omega_r the tangential part (normal to n) of omega_1 - omega_2 (a
 * wall: omega_1), body 1 gets the torque -M e and body 2 +M e, e = omega_r/
 * |omega_r|, M = min(mu_r R_r |F_n|, |omega_r|/(w_r dt)), w_r the inverse
 * moment of inertia of the pair about e (both movable sides): at most the
 * torque that stops the rolling within the sub-step. R_r is the rolling
 * radius, the reduced Gaussian curvature radius of the two surfaces at the
 * contact (a wall: the body's). A sphere rolling on a plane decelerates at
 * (5/7) mu_r g. Spin about n is not resisted. Without an elastic part a body
 * held on a slope by the rolling torque alone creeps at a speed proportional
 * to the sub-step, as with sliding friction.
 *
 * Usage: ContactParameters::rollingFriction (keyword rollingFriction; 0, the
 * default, switches it off).
 *
 * See also: SpringCoulombFriction, CollisionModel, docs/collisions.md.
 */
#ifndef COLLISION_ROLLINGRESISTANCE_HPP
#define COLLISION_ROLLINGRESISTANCE_HPP

#include "collision/ContactLaw.hpp"

namespace collision {

/**
 * The rolling resistance torque on body 2 (body 1 gets minus it).
 * @param coefficient mu_r >= 0
 * @param rollingRadius R_r > 0
 * @param normalForce F_n of the contact
 * @param n unit normal from 1 to 2
 * @param omega1, omega2 the bodies' angular velocities (a wall: zero)
 */
Vec3 rollingResistanceTorque(Scalar coefficient, Scalar rollingRadius, Scalar normalForce, const Vec3& n,
                             const Vec3& omega1, const Vec3& omega2, const ContactSide& s1,
                             const ContactSide& s2, Scalar dt);

}  // namespace collision

#endif
