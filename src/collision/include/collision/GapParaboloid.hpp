/**
 * @file GapParaboloid.hpp
 * @brief The gap between two smooth convex surfaces near their closest points,
 *        to second order, and the squeeze-film force it gives.
 *
 * With the closest points p1, p2 a gap h0 apart along the unit normal n (from
 * body 1 to body 2), the two surfaces near them are, for a tangent offset t,
 * -t^T S1 t/2 and h0 + t^T S2 t/2 along n (S1, S2 the curvature tensors of the
 * surfaces at p1 and p2, each for its own outward normal; a plane: S = 0), so
 *     h(t) = h0 + t^T K t/2,   K = S1 + S2,
 * an elliptic paraboloid with principal curvatures k1 <= k2 (the eigenvalues
 * of K on the plane normal to n). The Reynolds equation of the film,
 * div(h^3 grad p) = -12 mu U (U = -dh0/dt the approach speed), has for that
 * gap the exact solution
 *     p = 6 mu U / (h0^2 (k1 + k2) (1 + X^2 + Y^2)^2),
 * X = x sqrt(k1/(2 h0)) and Y = y sqrt(k2/(2 h0)) along the principal
 * directions, and its integral is the force F = 6 pi mu U R*^2/h0 with
 *     R*^2 = 2/(sqrt(k1 k2) (k1 + k2)),
 * R* the radius of the sphere that has the same squeeze force against a plane:
 * for two spheres R* = a1 a2/(a1 + a2), for a sphere and a plane R* = a (the
 * leading terms of Jeffrey & Onishi 1984 and Cox & Brenner 1967). It takes the
 * relative orientation of the two surfaces' principal directions into account
 * (two crossed cylinders and two parallel ones differ), which radii of
 * curvature combined as two spheres do not. The Reynolds equation solved on
 * the exact gap of spheres, spheroids and planes tends to this force as the
 * gap closes (validation/squeezeFilm).
 */
#ifndef COLLISION_GAPPARABOLOID_HPP
#define COLLISION_GAPPARABOLOID_HPP

#include "collision/Types.hpp"

namespace collision {

struct GapParaboloid {
  Scalar k1 = 0;  ///< smaller principal curvature of the gap [1/m]
  Scalar k2 = 0;  ///< larger principal curvature of the gap [1/m]

  /**
   * The gap's curvatures from the two surfaces' curvature tensors (world
   * frame, as Ellipsoid::curvatureTensor gives them) and the unit normal n;
   * both are projected onto the plane normal to n. A plane: S2 = 0.
   * @throws std::invalid_argument if the sum is not positive definite on the
   *         plane (a surface that is not convex, or two planes)
   */
  static GapParaboloid fromCurvatureTensors(const Mat3& S1, const Mat3& S2, const Vec3& n);

  /// R* = sqrt(2/(sqrt(k1 k2)(k1 + k2))): F = 6 pi mu U R*^2/h0 [m]
  Scalar squeezeRadius() const;
};

}  // namespace collision

#endif
