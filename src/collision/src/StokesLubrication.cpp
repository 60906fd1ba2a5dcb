#include "collision/StokesLubrication.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace collision {

StokesLubrication::StokesLubrication(Scalar viscosity, const LubricationParameters& parameters,
                                     bool wall)
    : viscosity_(viscosity), parameters_(parameters), wall_(wall) {
  if (!(std::isfinite(viscosity) && viscosity > 0)) {
    throw std::invalid_argument("lubrication: viscosity = " + Range::number(viscosity) +
                                " must be > 0");
  }
  parameters_.validate();
}

Scalar StokesLubrication::activationGap(Scalar r1, Scalar r2, Scalar cellSize) const {
  return parameters_.activationGap(r1, wall_ ? std::numeric_limits<Scalar>::infinity() : r2, cellSize);
}

Scalar StokesLubrication::reach(Scalar radiusBound, Scalar cellSize) const {
  // ratio form: 0.5 x_act (r1 + r2) <= reach(r1) + reach(r2); resolved-gap
  // form: the activation gap is at most kActivationOverResolvedGap resolved
  // gaps of the larger cell size
  if (parameters_.resolvedGapForm(false)) {
    return 0.5 * LubricationParameters::kActivationOverResolvedGap *
           parameters_.pairResolvedGapCells * cellSize;
  }
  return 0.5 * parameters_.pairActivation * radiusBound;
}

LubricationGapLaw StokesLubrication::gapLaw(Scalar r1, Scalar r2, Scalar squeezeRadius,
                                            Scalar cellSize) const {
  return LubricationGapLaw(r1, r2, viscosity_, parameters_, squeezeRadius, cellSize);
}

}  // namespace collision
