/**
 * @file TangentialLubrication.hpp
 * @brief The logarithmic lubrication terms of two smooth convex surfaces at
 *        a small gap, from the gap's paraboloid: the force and torques of
 *        relative sliding and rolling.
 *
 * Closest points p1, p2 a gap h0 apart along the unit normal n (from body 1
 * to body 2); S1, S2 the surfaces' curvature tensors there on the tangent
 * plane (P = I - n n^T; a plane: 0), K = S1 + S2 the gap's (GapParaboloid):
 * h(t) = h0 + t^T K t/2 for a tangent offset t, principal curvatures k1, k2.
 * Each body moves rigidly: v_k its velocity at p_k, U_k = P v_k its surface
 * velocity along the film, Omega_k its angular velocity. The film's gap
 * changes at the rate dh/dt = (v2 - v1).n + g.t, g = n x (Omega2 - Omega1)
 * - S1 U1 - S2 U2 (the surfaces turning and their curved shapes carried
 * along), and the Reynolds equation div(h^3 grad p) = 6 mu (U1 + U2).grad h
 * + 12 mu dh/dt has, for its part linear in t, the exact solution
 *     p = -(6 mu/h0^2) (M w).t / q^2,   q = h/h0,
 *     w = (S2 - S1)(U1 - U2) + 2 n x (Omega2 - Omega1),
 *     M = (2 tr(K) P + K)^+  (along the principal axes: 1/(3 k1 + 2 k2), 1/(2 k1 + 3 k2))
 * (the same change of variables as the squeeze film's exact solution,
 * GapParaboloid). The tractions on the surfaces, -(h/2) grad p -+ mu (U1 -
 * U2)/h along the film and the pressure on the inclined surfaces, integrated
 * over the film, diverge logarithmically as h0 -> 0; their ln(1/h0) terms,
 * with the log factor L for ln(1/h0), are
 *     F1 = pi mu R L [2 (U2 - U1) - 6 (P - 2 S1 K^+) M w],   F2 = -F1,
 *     T1 = 12 pi mu R L (K^+ M w) x n + (p1 - c1) x F1,
 *     T2 = -12 pi mu R L (K^+ M w) x n + (p2 - c2) x F2,
 * R = 1/sqrt(k1 k2) (the film's area scale, integral of dA/h = 2 pi R ln),
 * T_k about the body's centre c_k. For two spheres (S_k = P/a_k) these are
 * exactly the ln(1/xi) terms of the resistance functions Y^A, Y^B, Y^C of
 * Jeffrey and Onishi (1984), for a sphere and a plane those of Goldman, Cox
 * and Brenner (1967) (tests/collision/TangentialLubricationTest.cpp checks
 * both for every term); for spheroids they take the two surfaces' principal
 * directions and curvatures into account, to the same leading order in the
 * gap. Normal rotation (twist) has no logarithmic tangential force or
 * torque; where the surfaces' principal axes differ it has a logarithmic
 * normal force, which CubicGapCoupling carries. The Reynolds
 * equation solved on the exact gap of spheroids and planes gives these
 * coefficients to 0.6 % where the closest points are vertices of the
 * surfaces (validation/squeezeFilm, slidingFilm.py). Where they are not (a
 * tilted spheroid), the gap's cubic terms add a ln(1/h0) coupling between
 * normal and tangential motion, a normal force under sliding and a
 * tangential force under approach, of the order of these terms, which the
 * paraboloid does not contain: CubicGapCoupling adds it.
 *
 * The correction a resolved simulation adds below its activation gap x_act
 * is the part of these terms the mesh does not carry, L = ln(x_act/max(x,
 * x_sat)) (LubricationGapLaw::logFactor: the O(1) constants of the
 * resistance functions cancel in the difference).
 *
 * See also: GapParaboloid.hpp, CubicGapCoupling.hpp, LubricationLaw.hpp, CollisionModel,
 * docs/collisions.md.
 */
#ifndef COLLISION_TANGENTIALLUBRICATION_HPP
#define COLLISION_TANGENTIALLUBRICATION_HPP

#include "collision/FilmResistanceRate.hpp"
#include "collision/Types.hpp"

namespace collision {

class TangentialLubrication {
 public:
  /**
   * @param S1, S2 the surfaces' curvature tensors at the closest points (world
   *        frame, as Ellipsoid::curvatureTensor gives them; a plane: 0)
   * @param n the unit normal from body 1 to body 2
   * @throws std::invalid_argument unless viscosity > 0 and S1 + S2 is
   *         positive definite on the plane normal to n (GapParaboloid)
   */
  TangentialLubrication(const Mat3& S1, const Mat3& S2, const Vec3& n, Scalar viscosity);

  /// Two spheres of radii a1, a2 (a2 infinite: a plane), n from 1 to 2.
  static TangentialLubrication spheres(Scalar a1, Scalar a2, const Vec3& n, Scalar viscosity);

  /// The loads for the log factor L >= 0 (0 or less: none).
  FilmLoads loads(Scalar logFactor, const FilmSide& body1,
                                   const FilmSide& body2) const;

  /// The largest rate at which the terms alone change the bodies' motion, for
  /// the log factor L: filmResistanceRate of loads() (FilmResistanceRate.hpp),
  /// with the pair's mobility computed once (FilmMobility).
  Scalar rate(Scalar logFactor, const FilmMobility& mobility) const;

  /// R = 1/sqrt(k1 k2) [m]
  Scalar areaRadius() const { return radius_; }

 private:
  Vec3 n_;
  Mat3 P_;
  Mat3 S1_, S2_;
  Mat3 forceMap_;   ///< (P - 2 S1 K^+) M
  Mat3 torqueMap_;  ///< K^+ M
  Scalar radius_ = 0;
  Scalar mu_ = 0;
};

}  // namespace collision

#endif
