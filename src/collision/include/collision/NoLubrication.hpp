/**
 * @file NoLubrication.hpp
 * @brief No lubrication correction (it never acts: the bodies are not grown
 *        for it and no pair is recorded for it).
 *
 * See also: Lubrication, StokesLubrication.
 */
#ifndef COLLISION_NOLUBRICATION_HPP
#define COLLISION_NOLUBRICATION_HPP

#include "collision/Lubrication.hpp"

namespace collision {

class NoLubrication : public Lubrication {
 public:
  bool acts() const override { return false; }
  Scalar activationGap(Scalar, Scalar, Scalar) const override { return 0; }
  Scalar reach(Scalar, Scalar) const override { return 0; }
  LubricationGapLaw gapLaw(Scalar, Scalar, Scalar, Scalar) const override {
    return LubricationGapLaw();
  }
  bool tangential() const override { return false; }
  Scalar viscosity() const override { return 0; }
};

}  // namespace collision

#endif
