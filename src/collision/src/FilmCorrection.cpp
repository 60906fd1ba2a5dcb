#include "collision/FilmCorrection.hpp"

#include "collision/Range.hpp"

#include <cmath>
#include <stdexcept>

namespace collision {

FilmCorrection::FilmCorrection(Scalar viscosity) : viscosity_(viscosity) {
  if (!(std::isfinite(viscosity) && viscosity > 0)) {
    throw std::invalid_argument("film correction: viscosity = " + Range::number(viscosity) +
                                " must be > 0");
  }
}

}  // namespace collision
