/**
 * @file TangentialLubrication.hpp
 * @brief The logarithmic lubrication terms of two spheres (Jeffrey and
 *        Onishi 1984) or a sphere and a plane (Goldman, Cox and Brenner
 *        1967): the force and torques of relative sliding and rolling.
 *
 * Two spheres of radii a1, a2 (beta = a2/a1) at a small gap, d the unit
 * normal from 1 to 2, P = I - d d^T, U_k and Omega_k the velocities of the
 * centres and the angular velocities, u = U1 - U2. The terms of the
 * resistance functions singular in the gap are proportional to ln(1/x)
 * (x the gap ratio); the correction a resolved simulation adds below its
 * activation gap x_act is their part the mesh does not carry, with the
 * log factor L = ln(x_act/max(x, x_sat)) (LubricationGapLaw::logFactor: the
 * O(1) constants of the resistance functions cancel in the difference).
 * The hydrodynamic force on sphere 1 and the torques about the centres are
 *     F1 = -6 pi mu a1 L [A P u + B a1 Omega1 x d + ((1 + beta) A - B) a1 Omega2 x d],
 *     T1 = -8 pi mu a1^2 L [E d x u + G a1 P Omega1 + ((1 + beta) E - G) a1 P Omega2],
 *     F2 = -F1, T2 the same as T1 with 1 and 2 exchanged (beta -> 1/beta, d -> -d, u -> -u),
 * with the coefficients of the ln(1/xi) terms of Y^A_11, Y^B_11 and Y^C_11
 * (Jeffrey and Onishi 1984; Kim and Karrila 1991, chapter 11)
 *     A = (4/15) beta (2 + beta + 2 beta^2)/(1 + beta)^3,
 *     B = (2/15) beta (4 + beta)/(1 + beta)^2 = -(2/3) g_YB,   E = (3/4) B = -g_YB/2,
 *     G = (2/5) beta/(1 + beta).
 * The coefficients of Omega2 follow from the invariance under a rigid motion
 * of the pair (a rotation about the contact point moves no fluid through the
 * film): (1 + beta) E - G = beta^2/(10 (1 + beta)), the ln term of Y^C_12.
 * The force-rotation and torque-translation coefficients are those of one
 * symmetric resistance matrix (6 B = 8 E), so the terms dissipate energy for
 * any motion. A sphere and a plane (a2 infinite, the plane at rest): A = 8/15,
 * B = 2/15, E = 1/10, G = 2/5, the ln(a/h) terms of Goldman, Cox and Brenner
 * (1967); normal rotation (twist) has no logarithmic term.
 *
 * Spheroids: each body is replaced at its closest point by the sphere of its
 * Gaussian curvature radius there (its centre p1 - a1 d, p2 + a2 d), moving
 * rigidly with the body; the same local-sphere approximation as the
 * logarithmic terms of the normal law (LubricationLaw.hpp). No closed form is
 * known for the tangential terms of an elliptic paraboloidal gap.
 *
 * See also: LubricationLaw.hpp, CollisionModel, docs/collisions.md.
 */
#ifndef COLLISION_TANGENTIALLUBRICATION_HPP
#define COLLISION_TANGENTIALLUBRICATION_HPP

#include "collision/Types.hpp"

namespace collision {

/// The hydrodynamic loads of the terms on sphere 1 and 2 (force on 2: -force1),
/// the torques about the spheres' centres.
struct TangentialLubricationLoads {
  Vec3 force1 = Vec3::Zero();
  Vec3 torque1 = Vec3::Zero();
  Vec3 torque2 = Vec3::Zero();
};

class TangentialLubrication {
 public:
  /**
   * @param a1, a2 the spheres' radii (a2 infinite: a plane at rest)
   * @throws std::invalid_argument unless a1 > 0, a2 > 0 and viscosity > 0
   */
  TangentialLubrication(Scalar a1, Scalar a2, Scalar viscosity);

  /// The loads for the log factor L >= 0, the unit normal d from 1 to 2 and
  /// the motions of the centres (U2, Omega2 ignored for a plane).
  TangentialLubricationLoads loads(Scalar logFactor, const Vec3& d, const Vec3& u1,
                                   const Vec3& omega1, const Vec3& u2, const Vec3& omega2) const;

  /// The largest rate at which the terms alone change the motion, for the
  /// log factor L: L times the largest of 6 pi mu a1 A (1/m1 + 1/m2) and
  /// 8 pi mu a_k^3 G_k |I_k^-1| (k = 1, 2; |.| the Frobenius norm, an upper
  /// bound of the largest eigenvalue). Inverse masses 0: fixed.
  Scalar rate(Scalar logFactor, Scalar inverseMass1, const Mat3& inverseInertia1,
              Scalar inverseMass2, const Mat3& inverseInertia2) const;

  bool wall() const { return wall_; }

 private:
  bool wall_;
  Scalar a1_, a2_, mu_;
  Scalar A_, B_, E_, G_;  ///< sphere 1's coefficients
  Scalar E2_, G2_;        ///< sphere 2's E and G (beta -> 1/beta)
  Scalar beta_;
};

}  // namespace collision

#endif
