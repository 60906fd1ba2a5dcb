#include "collision/LubricationLaw.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace collision {

namespace {
constexpr Scalar kPi = 3.14159265358979323846;

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("lubrication: " + what);
}
}  // namespace

void LubricationParameters::validate() const {
  require(std::isfinite(saturation) && saturation > 0 && saturation < 1,
          "saturation = " + std::to_string(saturation) + " must be in (0, 1)");
  require(std::isfinite(pairActivation) && pairActivation > saturation && pairActivation <= 1,
          "pairActivation = " + std::to_string(pairActivation) +
              " must be in (saturation, 1]");
  require(std::isfinite(wallActivation) && wallActivation > saturation && wallActivation <= 1,
          "wallActivation = " + std::to_string(wallActivation) +
              " must be in (saturation, 1]");
}

Scalar pairLubricationLambda(Scalar xi, Scalar a1, Scalar a2) {
  const Scalar beta = a2 / a1;
  const Scalar b1 = 1 + beta;
  const Scalar b3 = b1 * b1 * b1;
  const Scalar lnInv = -std::log(xi);
  return 2 * beta * beta / b3 / xi + beta * (1 + 7 * beta + beta * beta) / (5 * b3) * lnInv +
         (1 + 18 * beta - 29 * beta * beta + 18 * beta * beta * beta + beta * beta * beta * beta) /
             (42 * b3) * xi * lnInv;
}

Scalar wallLubricationLambda(Scalar eps) {
  const Scalar lnEps = std::log(eps);
  return 1 / eps - lnEps / 5 - eps * lnEps / 21 + 0.9713;
}

Scalar pairLubricationCoefficient(Scalar gap, Scalar a1, Scalar a2, Scalar viscosity,
                                  const LubricationParameters& p) {
  if (!std::isfinite(a2)) return wallLubricationCoefficient(gap, a1, viscosity, p);
  const Scalar xi = 2 * gap / (a1 + a2);
  if (xi >= p.pairActivation || gap < 0) return 0;
  const Scalar xiEff = std::max(xi, p.saturation);
  return 6 * kPi * viscosity * a1 *
         (pairLubricationLambda(xiEff, a1, a2) - pairLubricationLambda(p.pairActivation, a1, a2));
}

Scalar wallLubricationCoefficient(Scalar gap, Scalar a, Scalar viscosity,
                                  const LubricationParameters& p) {
  const Scalar eps = gap / a;
  if (eps >= p.wallActivation || gap < 0) return 0;
  const Scalar epsEff = std::max(eps, p.saturation);
  return 6 * kPi * viscosity * a *
         (wallLubricationLambda(epsEff) - wallLubricationLambda(p.wallActivation));
}

}  // namespace collision
