/**
 * @file Lubrication.hpp
 * @brief The normal lubrication correction of a pair or wall model: the
 *        interface of the lubrication laws.
 *
 * A law acts below its activation gap: a ratio of the radii (pairs:
 * 2h/(R1 + R2), walls: h/R, with R the Gaussian curvature radii at the
 * closest points) or a number of cells of the bodies' cell size
 * (LubricationParameters::activationRatio), and gives,
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

  /// Whether the law ever acts (false: no reach, no pair recorded for it).
  virtual bool acts() const = 0;

  /// The gap below which the law acts for the curvature radii r1, r2
  /// (r2 = infinity: a wall) and the pair's cell size (0 with no law);
  /// nondecreasing in r1 and r2: upper bounds of the radii bound it.
  virtual Scalar activationGap(Scalar r1, Scalar r2, Scalar cellSize) const = 0;

  /// A body's reach for the pair law: half the largest pair activation gap a
  /// body of curvature radii up to radiusBound can take part in, when no
  /// body's cell size exceeds cellSize (two bodies' reaches together bound
  /// their pair's activation gap).
  virtual Scalar reach(Scalar radiusBound, Scalar cellSize) const = 0;

  /// The law of one pair against its gap; r1, r2 the Gaussian curvature radii
  /// (r2 = infinity: a wall), squeezeRadius R* of the gap's paraboloid
  /// (GapParaboloid.hpp; spheres: r1 r2/(r1 + r2), a sphere and a wall: r1),
  /// cellSize the pair's cell size (for the resolved-gap form).
  virtual LubricationGapLaw gapLaw(Scalar r1, Scalar r2, Scalar squeezeRadius,
                                   Scalar cellSize) const = 0;

  /// Whether the logarithmic tangential and rotational terms act too
  /// (TangentialLubrication.hpp, with the gap law's log factor).
  virtual bool tangential() const = 0;

  /// The dynamic viscosity mu [Pa s] (0: no law).
  virtual Scalar viscosity() const = 0;
};

}  // namespace collision

#endif
