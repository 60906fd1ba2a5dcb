/**
 * @file FilmCorrection.hpp
 * @brief The film correction of the coupling's lagged hydrodynamic force
 *        for pairs closer than their film gap.
 *
 * The flow solver's force responds to the velocities at the start of its
 * step; in a film thinner than a cell it damps the relative normal motion
 * far more than m/dt allows, and a lagged damping makes the body oscillate
 * with growing amplitude. A pair (walls included) whose gap h is below its
 * film gap gets the force -D (u_n - u_n,ref) n, implicit in the end velocity
 * (CollisionModel::dampingForces), with
 *     D = 6 pi mu R^2/max(h, filmGap/4),
 * R the squeeze radius of the gap's paraboloid at the closest points
 * (GapParaboloid.hpp: for spheres the reduced radius, for a sphere and a wall
 * its radius), so that D is the leading squeeze-film damping at the gap
 * max(h, filmGap/4), times a scale s (default 1: the estimate; other values
 * for the results' sensitivity to it, validation/stabiliserSensitivity).
 * Each body carries its film gap (CollisionBody::filmGap, 0: none); a pair's
 * is the larger of its bodies'.
 *
 * Usage: constructed by the caller with the viscosity mu > 0 [Pa s] and the
 * scale s in kDampingScaleRange, and given to CollisionModel (none: no film
 * correction).
 *
 * See also: CollisionModel, docs/collisions.md.
 */
#ifndef COLLISION_FILMCORRECTION_HPP
#define COLLISION_FILMCORRECTION_HPP

#include "collision/Range.hpp"
#include "collision/Types.hpp"

#include <algorithm>

namespace collision {

class FilmCorrection {
 public:
  static constexpr Range kDampingScaleRange{0, 100, true, false};

  /// @throws std::invalid_argument unless viscosity is finite and > 0 and
  /// dampingScale in kDampingScaleRange
  explicit FilmCorrection(Scalar viscosity, Scalar dampingScale = 1);

  Scalar viscosity() const { return viscosity_; }
  Scalar dampingScale() const { return dampingScale_; }

  /// The film gap of a pair from its bodies' (a wall has none: 0).
  static Scalar pairFilmGap(Scalar filmGap1, Scalar filmGap2) {
    return std::max(filmGap1, filmGap2);
  }

  /// D for the reduced radius r at the gap h below the pair's film gap.
  Scalar coefficient(Scalar r, Scalar gap, Scalar filmGap) const {
    return dampingScale_ * 6 * kPi * viscosity_ * r * r / std::max(gap, Scalar(0.25) * filmGap);
  }

 private:
  Scalar viscosity_;
  Scalar dampingScale_;
};

}  // namespace collision

#endif
