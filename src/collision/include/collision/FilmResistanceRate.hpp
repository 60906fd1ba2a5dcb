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
 * A film law acts through the relative motion of the two surfaces at the
 * closest points, z = (V, w) with V = v1 + Omega1 x r1 - v2 - Omega2 x r2 and
 * w = Omega1 - Omega2 (r1, r2 the arms from the centres), and gives body 1 a
 * force f at its closest point and a moment m, body 2 their opposites at its
 * own: q enters as z = B q and the loads are B^T (f, m), so R = B^T N B with
 * N the 6 x 6 resistance of the film, (f, m) = -N z. With M = D^2 the bodies'
 * mobility and H = B M B^T that of the relative motion,
 *     |D R D|_F^2 = tr(D R^T M R D) = tr(N^T H N H),
 * six evaluations of the law and no square roots (FilmMobility holds H, once
 * per pair for every law of the pair). Both film laws of the module have this
 * form (TangentialLubrication, CubicGapCoupling; tests/collision check the
 * identity against D R D assembled column by column).
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

/// The mobility H = B M B^T of the relative motion (V, w) of two bodies at
/// their closest points (arms from the centres), from their inverse masses
/// and world-frame inverse inertia tensors (0: a fixed body or a wall).
struct FilmMobility {
  FilmMobility(const Vec3& arm1, Scalar inverseMass1, const Mat3& inverseInertia1,
               const Vec3& arm2, Scalar inverseMass2, const Mat3& inverseInertia2);
  Vec3 arm1;
  Vec3 arm2;
  Eigen::Matrix<Scalar, 6, 6> relative;
};

/// The Frobenius norm of D R D for the law's loads (the law as above).
Scalar filmResistanceRate(const FilmLaw& loads, const FilmMobility& mobility);

/// The same, the mobility from the bodies' arms, inverse masses and inertias.
Scalar filmResistanceRate(const FilmLaw& loads, const Vec3& arm1, Scalar inverseMass1,
                          const Mat3& inverseInertia1, const Vec3& arm2, Scalar inverseMass2,
                          const Mat3& inverseInertia2);

}  // namespace collision

#endif
