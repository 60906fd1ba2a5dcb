#include "collision/LubricationLaw.hpp"

#include <algorithm>
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

namespace {
// the pair law's lambda = A/xi + B ln(1/xi) + C xi ln(1/xi): its coefficients
struct PairTerms {
  Scalar A, B, C;
};
PairTerms pairTerms(Scalar a1, Scalar a2) {
  const Scalar beta = a2 / a1;
  const Scalar b1 = 1 + beta;
  const Scalar b3 = b1 * b1 * b1;
  return {2 * beta * beta / b3, beta * (1 + 7 * beta + beta * beta) / (5 * b3),
          (1 + 18 * beta - 29 * beta * beta + 18 * beta * beta * beta + beta * beta * beta * beta) /
              (42 * b3)};
}

// antiderivatives of lambda in the gap ratio (any constant)
Scalar pairLambdaPrimitive(Scalar xi, const PairTerms& t) {
  const Scalar ln = std::log(xi);
  return t.A * ln + t.B * (xi - xi * ln) + t.C * (xi * xi / 4 - xi * xi * ln / 2);
}
Scalar wallLambdaPrimitive(Scalar eps) {
  const Scalar ln = std::log(eps);
  return ln - (eps * ln - eps) / 5 - (eps * eps * ln / 2 - eps * eps / 4) / 21 + 0.9713 * eps;
}

// int_0^x [lambda(max(s, sat)) - lambda(act)] ds for x in [0, act], from the
// law's lambda and its antiderivative L (0 for x <= 0, constant beyond act)
template <class Lambda, class Primitive>
Scalar correctionPrimitive(Scalar x, Scalar sat, Scalar act, Lambda lambda, Primitive L) {
  if (!(x > 0)) return 0;
  x = std::min(x, act);
  const Scalar lambdaAct = lambda(act);
  if (x <= sat) return (lambda(sat) - lambdaAct) * x;
  return (lambda(sat) - lambdaAct) * sat + (L(x) - L(sat)) - lambdaAct * (x - sat);
}
}  // namespace

Scalar pairLubricationLambda(Scalar xi, Scalar a1, Scalar a2) {
  const PairTerms t = pairTerms(a1, a2);
  const Scalar lnInv = -std::log(xi);
  return t.A / xi + t.B * lnInv + t.C * xi * lnInv;
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

Scalar pairLubricationIntegral(Scalar h0, Scalar h1, Scalar a1, Scalar a2, Scalar viscosity,
                               const LubricationParameters& p) {
  if (!std::isfinite(a2)) return wallLubricationIntegral(h0, h1, a1, viscosity, p);
  const PairTerms t = pairTerms(a1, a2);
  auto lambda = [&](Scalar xi) { return pairLubricationLambda(xi, a1, a2); };
  auto L = [&](Scalar xi) { return pairLambdaPrimitive(xi, t); };
  const Scalar scale = 2 / (a1 + a2);  // xi = scale h
  auto G = [&](Scalar h) { return correctionPrimitive(scale * h, p.saturation, p.pairActivation, lambda, L); };
  return 6 * kPi * viscosity * a1 / scale * (G(h1) - G(h0));
}

Scalar wallLubricationIntegral(Scalar h0, Scalar h1, Scalar a, Scalar viscosity,
                               const LubricationParameters& p) {
  auto G = [&](Scalar h) {
    return correctionPrimitive(h / a, p.saturation, p.wallActivation, wallLubricationLambda,
                               wallLambdaPrimitive);
  };
  return 6 * kPi * viscosity * a * a * (G(h1) - G(h0));
}

}  // namespace collision
