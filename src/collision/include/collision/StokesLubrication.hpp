/**
 * @file StokesLubrication.hpp
 * @brief The Stokes lubrication correction of two spheres (Jeffrey and
 *        Onishi 1984) or a sphere and a plane (Cox and Brenner 1967) between
 *        the activation and the saturation gaps (LubricationLaw.hpp).
 *
 * Usage (LubricationParameters, defaults and ranges there):
 * | parameter      | meaning                                   | default | range |
 * |----------------|-------------------------------------------|---------|-------|
 * | viscosity      | dynamic viscosity mu [Pa s], from the caller |      | > 0 |
 * | pairActivation | 2h/(R1 + R2) below which a pair law acts  | 0.025   | (saturation, 1] |
 * | wallActivation | h/R below which a wall law acts           | 0.075   | (saturation, 1] |
 * | pairResolvedGapCells | > 0: the resolved-gap form, delta in cells (cellSize) | 0 (ratio form) | 0 or (0, 8] |
 * | wallResolvedGapCells | > 0: the same for walls                 | 0 (ratio form) | 0 or (0, 8] |
 * | saturation     | gap ratio below which it is frozen        | 1e-3    | (0, 1) |
 * | tangential     | the logarithmic tangential terms too      | true    | true, false |
 *
 * See also: Lubrication, NoLubrication, PairModel, WallModel; docs/collisions.md.
 */
#ifndef COLLISION_STOKESLUBRICATION_HPP
#define COLLISION_STOKESLUBRICATION_HPP

#include "collision/Lubrication.hpp"

namespace collision {

class StokesLubrication : public Lubrication {
 public:
  /**
   * @param wall true: the law of a body and a plane wall (wallActivation),
   *        false: of two bodies (pairActivation)
   * @throws std::invalid_argument on viscosity <= 0 or parameters out of range
   */
  StokesLubrication(Scalar viscosity, const LubricationParameters& parameters, bool wall);

  Scalar viscosity() const override { return viscosity_; }
  const LubricationParameters& parameters() const { return parameters_; }

  bool acts() const override { return true; }
  Scalar activationGap(Scalar r1, Scalar r2, Scalar cellSize) const override;
  Scalar reach(Scalar radiusBound, Scalar cellSize) const override;
  LubricationGapLaw gapLaw(Scalar r1, Scalar r2, Scalar squeezeRadius,
                           Scalar cellSize) const override;
  bool tangential() const override { return parameters_.tangential; }

 private:
  Scalar viscosity_;
  LubricationParameters parameters_;
  bool wall_;
};

}  // namespace collision

#endif
