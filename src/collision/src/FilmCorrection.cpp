#include "collision/FilmCorrection.hpp"

#include "collision/Range.hpp"

#include <cmath>
#include <stdexcept>

namespace collision {

FilmCorrection::FilmCorrection(Scalar viscosity, Scalar dampingScale)
    : viscosity_(viscosity), dampingScale_(dampingScale) {
  if (!(std::isfinite(viscosity) && viscosity > 0)) {
    throw std::invalid_argument("film correction: viscosity = " + Range::number(viscosity) +
                                " must be > 0");
  }
  if (!kDampingScaleRange.contains(dampingScale)) {
    throw std::invalid_argument("film correction: " + outOfRangeMessage("dampingScale",
                                                                        dampingScale,
                                                                        kDampingScaleRange));
  }
}

}  // namespace collision
