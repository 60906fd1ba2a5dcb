/**
 * @file Lubrication.hpp
 * @brief The normal lubrication correction of a pair or wall model: the
 *        interface of the lubrication laws.
 *
 * A law acts below its activation gap ratio (pairs: 2h/(R1 + R2), walls:
 * h/R, with R the Gaussian curvature radii at the closest points) and gives,
 * for one pair of radii and the squeeze radius of the gap's paraboloid, its
 * coefficient against the gap (LubricationGapLaw),
 * which CollisionModel::dampingForces applies implicitly.
 * The logarithmic tangential terms (TangentialLubrication) share its
 * activation and saturation gaps.
 * Implementations: NoLubrication, StokesLubrication.
 */
#ifndef COLLISION_LUBRICATION_HPP
#define COLLISION_LUBRICATION_HPP

#include "collision/LubricationLaw.hpp"

namespace collision {

class Lubrication {
 public:
  virtual ~Lubrication() = default;

  /// The gap ratio below which the law acts; 0: it never acts (no reach).
  virtual Scalar activation() const = 0;

  /// The law of one pair against its gap; r1, r2 the Gaussian curvature radii
  /// (r2 = infinity: a wall), squeezeRadius R* of the gap's paraboloid
  /// (GapParaboloid.hpp; spheres: r1 r2/(r1 + r2), a sphere and a wall: r1).
  virtual LubricationGapLaw gapLaw(Scalar r1, Scalar r2, Scalar squeezeRadius) const = 0;

  /// Whether the logarithmic tangential and rotational terms act too
  /// (TangentialLubrication.hpp, with the gap law's log factor).
  virtual bool tangential() const = 0;

  /// The dynamic viscosity mu [Pa s] (0: no law).
  virtual Scalar viscosity() const = 0;
};

}  // namespace collision

#endif
