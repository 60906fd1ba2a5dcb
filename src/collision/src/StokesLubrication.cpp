#include "collision/StokesLubrication.hpp"

#include <cmath>
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

Scalar StokesLubrication::activation() const {
  return wall_ ? parameters_.wallActivation : parameters_.pairActivation;
}

LubricationGapLaw StokesLubrication::gapLaw(Scalar r1, Scalar r2, Scalar squeezeRadius) const {
  return LubricationGapLaw(r1, r2, viscosity_, parameters_, squeezeRadius);
}

}  // namespace collision
