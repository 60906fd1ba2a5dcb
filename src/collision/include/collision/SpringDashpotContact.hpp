/**
 * @file SpringDashpotContact.hpp
 * @brief The normal contact: a linear spring-dashpot (ContactLaw.hpp) with
 *        its contact time, the overlap cap and the sustained-load rule.
 *
 * At the first touch the contact time is the nominal T_c, shortened to
 * pi cap/u_n for a fast impact (the overlap stays below the cap); k_n and
 * eta_n follow from the effective mass and are kept for the whole contact,
 * the elastic force integrated incrementally (dF = k_n d(delta)). While the
 * bodies approach, the spring must take up the approach's kinetic energy and
 * the load's work within the overlap still allowed D = cap - overlap:
 * F D + k_n D^2/2 >= m_eff u_n^2/2 + W D (F the spring force); where it
 * cannot (a body swinging into the contact, the trailing body of a stacked
 * pair whose leading one a wall stops) it is stiffened to meet it, at most
 * to the contact time ContactLoading::shortestContactTime (for the current
 * m_eff and for the contact's own T_c, which the sub-steps follow), and only
 * below the cap (D > 0: beyond it no spring meets the check). A
 * sustained load W pressing the pair together stiffens the spring to
 * k_n >= W/(f cap) (the static overlap at most the fraction f of the cap,
 * ContactParameters::sustainedLoadOverlap, default 1/2).
 *
 * Usage: restitution e is ContactParameters::restitution (default 0.97, in
 * kRestitutionRange), f its sustainedLoadOverlap; the cap (maxOverlap x the
 * smallest semi-axis) and the nominal T_c come from CollisionModel.
 *
 * See also: PairModel, WallModel, CollisionModel; docs/collisions.md.
 */
#ifndef COLLISION_SPRINGDASHPOTCONTACT_HPP
#define COLLISION_SPRINGDASHPOTCONTACT_HPP

#include "collision/ContactLaw.hpp"

namespace collision {

/// What a contact under way carries from call to call.
struct ContactState {
  Scalar contactTime = 0;  ///< T_c of the contact (shortened if the overlap needs it)
  Scalar springForce = 0;  ///< elastic normal force, updated incrementally
  Scalar stiffness = 0;    ///< k_n of the contact (0: set at the next call)
  Scalar overlap = 0;      ///< overlap of the last call
  Vec3 force = Vec3::Zero();  ///< the contact force on the second body in the last call
  /// the tangential spring's elongation (coulombSpring friction) and the
  /// tangential slip velocity of the last call, which its trapezoidal
  /// integration over the time between two calls needs
  Vec3 tangentialSpring = Vec3::Zero();
  Vec3 tangentialSlip = Vec3::Zero();
};

/// What the contact's spring sees at one evaluation.
struct ContactLoading {
  Scalar overlap = 0;      ///< the overlap (>= 0)
  Scalar normalSpeed = 0;  ///< u_n at the contact point (< 0: approaching)
  Scalar inverseMass = 0;  ///< 1/m_eff along n of the pair (> 0)
  Scalar cap = 0;                  ///< the largest overlap allowed
  Scalar load = 0;                 ///< the sustained load pressing the pair together (N, >= 0)
  Scalar shortestContactTime = 0;  ///< the shortest contact time the sub-step resolves (> 0)
};

class SpringDashpotContact {
 public:
  /// @throws std::invalid_argument if restitution or sustainedLoadOverlap is
  /// outside its ContactParameters range
  explicit SpringDashpotContact(
      Scalar restitution,
      Scalar sustainedLoadOverlap = ContactParameters().sustainedLoadOverlap);

  Scalar restitution() const { return restitution_; }
  Scalar sustainedLoadOverlap() const { return sustainedLoadOverlap_; }

  /// The state of a first touch at normal speed un (< 0: approaching) with the nominal contact time.
  ContactState firstTouch(Scalar contactTime, Scalar un, Scalar cap) const;

  /**
   * Advance the state c to the loading l and return the normal force on
   * body 2 along n (normalForce()); sets c's stiffness, overlap, spring force
   * and contact time (not its force).
   * @param stiffened incremented for each stiffening of the spring
   */
  Scalar force(ContactState& c, const ContactLoading& l, long& stiffened) const;

 private:
  Scalar restitution_;
  Scalar sustainedLoadOverlap_;
};

}  // namespace collision

#endif
