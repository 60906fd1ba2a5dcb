/**
 * @file ContactLaw.hpp
 * @brief Soft contact: linear spring-dashpot in the normal direction with the
 *        rotation-aware effective mass (the functions SpringDashpotContact
 *        and the friction laws use).
 *
 * Normal force on body 2 (n from body 1 to body 2, overlap delta > 0, normal
 * relative speed u_n = (v_2 - v_1).n at the contact point):
 *     F_n = (k_n delta - eta_n u_n) n,
 *     k_n = m_eff (pi^2 + ln^2 e)/T_c^2,  eta_n = -2 m_eff ln(e)/T_c
 * (physics-references.md 3): the contact point's normal speed is a damped
 * oscillator that leaves the contact after T_c with -e times its impact speed.
 * m_eff is the effective mass of the contact point along n,
 *     1/m_eff = sum over the movable bodies of 1/m_i + (r_i x n).I_i^-1 (r_i x n),
 * r_i from the body's centre to the contact point: for a spheroid hitting off
 * its centre line the rotation is part of the rebound and the restitution of
 * the contact point is still e (with 1/m_eff = 1/m_1 + 1/m_2 it is not).
 * The law is kept to the end of the contact (delta back to 0), the short
 * tensile end of the linear law included: it is what makes the restitution e.
 * m_eff changes while a turning body moves the contact point;
 * SpringDashpotContact keeps k_n and eta_n of the first touch for the whole
 * contact (a k_n that follows m_eff is not conservative).
 * Tangential: SpringCoulombFriction (default) or CoulombFriction.
 */
#ifndef COLLISION_CONTACTLAW_HPP
#define COLLISION_CONTACTLAW_HPP

#include "collision/Range.hpp"
#include "collision/Types.hpp"

#include <string>
#include <vector>

namespace collision {

/// The defaults are the member initialisers, the allowed values the k...Range constants.
struct ContactParameters {
  /// dry coefficient of restitution e, in kRestitutionRange
  Scalar restitution = 0.97;
  static constexpr Range kRestitutionRange{0, 1, true, false};
  /// Coulomb friction coefficient mu, in kFrictionRange (0: frictionless)
  Scalar friction = 0;
  static constexpr Range kFrictionRange{0, 100};
  /// the tangential law, one of frictionModels(): coulombSpring (a tangential
  /// spring bounded by mu |F_n|: static and sliding friction) or
  /// coulombSliding (sliding friction only)
  std::string frictionModel = "coulombSpring";
  /// rolling friction coefficient mu_r, in kRollingFrictionRange (0: none):
  /// the rolling resistance torque is at most mu_r R_r |F_n| (RollingResistance)
  Scalar rollingFriction = 0;
  static constexpr Range kRollingFrictionRange{0, 1};
  /// the static overlap a sustained load W may give a contact, over the
  /// overlap cap: the spring is stiffened to k_n >= W/(fraction x cap), so
  /// that an impact on a loaded contact still has the rest of the cap
  /// (SpringDashpotContact). A rule, not a fit: docs/collisions.md gives
  /// the results' sensitivity to it (validation/stabiliserSensitivity).
  Scalar sustainedLoadOverlap = 0.5;
  static constexpr Range kSustainedLoadOverlapRange{0, 1, true, false};
  static const std::vector<std::string>& frictionModels();

  /// @throws std::invalid_argument naming the parameter and its allowed range
  void validate() const;
};

/// The rigid-body data a contact needs from one side (a wall: movable = false).
struct ContactSide {
  bool movable = false;
  Scalar inverseMass = 0;
  Mat3 inverseInertia = Mat3::Zero();  ///< world frame
  Vec3 arm = Vec3::Zero();             ///< contact point - centre
};

/// 1/m along the unit direction d at the contact point, summed over both sides.
Scalar inverseEffectiveMass(const ContactSide& s1, const ContactSide& s2, const Vec3& d);

struct SpringDashpot {
  Scalar stiffness = 0;  ///< k_n
  Scalar damping = 0;    ///< eta_n
};

/// k_n and eta_n for the effective mass, restitution e and contact time T_c.
SpringDashpot springDashpot(Scalar effectiveMass, Scalar restitution, Scalar contactTime);

/// The same oscillator given its stiffness: eta_n = -2 k_n T_c ln(e)/(pi^2 + ln^2 e).
SpringDashpot springDashpotOfStiffness(Scalar stiffness, Scalar restitution, Scalar contactTime);

/**
 * The normal force on body 2 along n, F_e - eta_n u_n; at F_e = 0 the dashpot
 * may push but not pull (the dashpot's tensile end belongs to the spring's
 * unloading: once the elastic force is spent, no pull).
 */
Scalar normalForce(Scalar elasticForce, Scalar normalSpeed, const SpringDashpot& law);

/**
 * The contact force on body 2 (body 1 gets minus it): normalForce() n plus
 * CoulombFriction(friction).
 * @param elasticForce the spring's force F_e >= 0: k_n delta for a constant
 *        stiffness (SpringDashpotContact integrates it incrementally)
 * @param n unit normal from 1 to 2
 * @param relativeVelocity (v_2 - v_1) at the contact point
 */
Vec3 contactForce(Scalar elasticForce, const Vec3& n, const Vec3& relativeVelocity,
                  const SpringDashpot& law, const ContactSide& s1, const ContactSide& s2,
                  Scalar friction, Scalar dt);

}  // namespace collision

#endif
