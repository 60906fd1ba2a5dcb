/**
 * @file CubicGapCoupling.hpp
 * @brief The logarithmic coupling of normal and tangential motion in the film
 *        between two smooth convex surfaces, from the gap's cubic terms: a
 *        tangential force and a moment under approach, and by reciprocity a
 *        normal force under sliding and rotation.
 *
 * Closest points p1, p2 a gap h0 apart along the unit normal n (from body 1
 * to body 2), S1, S2 the surfaces' curvature tensors there and C1, C2 their
 * third derivatives (each for its own outward normal, Ellipsoid::
 * surfaceThirdDerivative; a plane: 0). The gap is, for a tangent offset t,
 *     h(t) = h0 + t^T K t/2 + Gamma(t, t, t)/6,   K = S1 + S2, Gamma = C1 + C2.
 * Where the closest points are vertices of both surfaces (spheres, a spheroid
 * broadside or tip-on, two spheroids side by side) Gamma and C2 - C1 vanish
 * and so does this coupling. Elsewhere (a spheroid tilted to a wall) the
 * squeeze pressure acting on the cubic slopes of the surfaces, and the odd
 * pressure the cubic terms add to the squeeze film (found through the
 * adjoint of the sliding problem, whose solution is TangentialLubrication's
 * pressure), give body 1, approaching body 2 at the speed V, the ln(1/h0)
 * force and moment about p1, in the principal axes e_m of K (curvatures k_m,
 * o the other axis):
 *     F = pi mu R V [3/(k1 + k2) sum_a D_aam/k_a + (S2 - S1) j/2],  D = C2 - C1,
 *     j_m = 36/((k1 + k2)(3 k_m + 2 k_o)) [-(7 k_m + 2 k_o) Gamma_mmm/(6 k_m^2)
 *                                         - (k_m + 2 k_o) Gamma_moo/(2 k_m k_o)],
 *     T = -pi mu R V j x n - 12 pi mu R V/(k1 + k2) [(S1 K^-1)_21 - (S1 K^-1)_12] e1 x e2,
 * R = 1/sqrt(k1 k2); the last term is the twist that the squeeze pressure
 * gives surfaces whose principal axes are not K's. The film's resistance is
 * symmetric, so a relative motion of the surfaces (u_k the velocity of body k
 * at p_k, Omega_k its angular velocity) gives body 1 the normal force
 *     F_n = (F.(u1 - u2) + T.(Omega1 - Omega2))/V
 * along n, and the loads are
 *     F1 = L [((u1 - u2).n) F/V + F_n n],   F2 = -F1,
 *     T1 = L ((u1 - u2).n) T/V + (p1 - c1) x F1,
 *     T2 = -L ((u1 - u2).n) T/V - (p2 - c2) x F1,
 * with the log factor L of TangentialLubrication. The closed form agrees with
 * the Reynolds equation solved on the exact gap (validation/squeezeFilm,
 * cubicCoupling.py). The coupling's resistance alone is not dissipative: it
 * is, together with the normal squeeze film, whose 1/h0 coefficient
 * dominates its square at the gaps where it acts.
 *
 * See also: TangentialLubrication.hpp, GapParaboloid.hpp, CollisionModel,
 * docs/collisions.md.
 */
#ifndef COLLISION_CUBICGAPCOUPLING_HPP
#define COLLISION_CUBICGAPCOUPLING_HPP

#include "collision/FilmResistanceRate.hpp"
#include "collision/Types.hpp"

namespace collision {

class CubicGapCoupling {
 public:
  /**
   * @param S1, S2 the surfaces' curvature tensors at the closest points
   * @param C1, C2 their third derivatives (C[k](i, j) = C_ijk, world frame)
   * @param n the unit normal from body 1 to body 2
   * @throws std::invalid_argument unless viscosity > 0 and S1 + S2 is
   *         positive definite on the plane normal to n
   */
  CubicGapCoupling(const Mat3& S1, const Mat3& S2, const Tensor3& C1, const Tensor3& C2,
                   const Vec3& n, Scalar viscosity);

  /// The loads for the log factor L >= 0 (0 or less: none).
  FilmLoads loads(Scalar logFactor, const FilmSide& body1, const FilmSide& body2) const;

  /// The tangential force on body 1 for a unit approach speed and L = 1 [N s/m].
  const Vec3& approachForce() const { return force_; }
  /// Its moment about the closest point p1 [N s].
  const Vec3& approachMoment() const { return moment_; }

 private:
  Vec3 n_;
  Vec3 force_ = Vec3::Zero();
  Vec3 moment_ = Vec3::Zero();
};

}  // namespace collision

#endif
