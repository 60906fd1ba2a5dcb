/**
 * @file FilmResistanceRate.hpp
 * @brief The largest rate at which a linear film law alone changes the motion
 *        of the two bodies it couples: the bound that keeps the law's explicit
 *        application in a sub-step from reversing the relative motion.
 *
 * For loads L = -R q linear in q = (v1, Omega1, v2, Omega2) (the centres'
 * velocities and angular velocities), the rate is the Frobenius norm of
 * D R D, D = diag(sqrt(m1^-1) I, sqrt(I1^-1), sqrt(m2^-1) I, sqrt(I2^-1)): an
 * upper bound of the largest eigenvalue of the mobility times the resistance,
 * unit-consistent whatever the bodies' sizes. Inverse masses 0: fixed bodies.
 *
 * See also: TangentialLubrication.hpp, CubicGapCoupling.hpp.
 */
#ifndef COLLISION_FILMRESISTANCERATE_HPP
#define COLLISION_FILMRESISTANCERATE_HPP

#include "collision/Types.hpp"

#include <functional>

namespace collision {

/// The loads of a film law on the two bodies (force on 2: -force1), the
/// torques about the bodies' centres.
struct FilmLoads {
  Vec3 force1 = Vec3::Zero();
  Vec3 torque1 = Vec3::Zero();
  Vec3 torque2 = Vec3::Zero();
};

/// The motion of one body: the arm from its centre to its closest point, and
/// its centre's velocity and angular velocity (a plane at rest: all zero).
struct FilmSide {
  Vec3 arm = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 angularVelocity = Vec3::Zero();
};

/// The loads of a linear film law for the motions of its two sides.
using FilmLaw = std::function<FilmLoads(const FilmSide&, const FilmSide&)>;

/// The Frobenius norm of D R D for the law's loads at these arms and mobilities.
Scalar filmResistanceRate(const FilmLaw& loads, const Vec3& arm1, Scalar inverseMass1,
                          const Mat3& inverseInertia1, const Vec3& arm2, Scalar inverseMass2,
                          const Mat3& inverseInertia2);

}  // namespace collision

#endif
