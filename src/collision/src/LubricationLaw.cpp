#include "collision/LubricationLaw.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace collision {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("lubrication: " + what);
}
}  // namespace

void LubricationParameters::validate() const {
  require(kSaturationRange.contains(saturation),
          outOfRangeMessage("saturation", saturation, kSaturationRange));
  require(activationRange().contains(pairActivation),
          outOfRangeMessage("pairActivation", pairActivation, activationRange()) +
              " (above saturation)");
  require(activationRange().contains(wallActivation),
          outOfRangeMessage("wallActivation", wallActivation, activationRange()) +
              " (above saturation)");
  require(pairResolvedGapCells == 0 || kCellsRange.contains(pairResolvedGapCells),
          outOfRangeMessage("pairResolvedGapCells", pairResolvedGapCells, kCellsRange) +
              " (or 0: the ratio pairActivation)");
  require(wallResolvedGapCells == 0 || kCellsRange.contains(wallResolvedGapCells),
          outOfRangeMessage("wallResolvedGapCells", wallResolvedGapCells, kCellsRange) +
              " (or 0: the ratio wallActivation)");
}

Scalar LubricationParameters::resolvedGapRatio(Scalar a1, Scalar a2, Scalar cellSize) const {
  const bool wall = !std::isfinite(a2);
  const Scalar cells = wall ? wallResolvedGapCells : pairResolvedGapCells;
  if (cells == 0) return 0;
  // (the message is built only on failure: this runs once per lubricated pair and evaluation)
  if (!(cellSize > 0)) {
    require(false, std::string(wall ? "wallResolvedGapCells" : "pairResolvedGapCells") +
                       " needs the bodies' cell size (> 0), given " + Range::number(cellSize));
  }
  return cells * cellSize / (wall ? a1 : 0.5 * (a1 + a2));
}

Scalar LubricationParameters::activationRatio(Scalar a1, Scalar a2, Scalar cellSize) const {
  const bool wall = !std::isfinite(a2);
  if (!resolvedGapForm(wall)) return wall ? wallActivation : pairActivation;
  return std::clamp(kActivationOverResolvedGap * resolvedGapRatio(a1, a2, cellSize), saturation,
                    kMaxActivation);
}

Scalar LubricationParameters::activationGap(Scalar a1, Scalar a2, Scalar cellSize) const {
  const Scalar radius = std::isfinite(a2) ? 0.5 * (a1 + a2) : a1;
  return activationRatio(a1, a2, cellSize) * radius;
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
  const LubricationGapLaw law(a1, a2, viscosity, p);
  return law.primitive(h1) - law.primitive(h0);
}

Scalar wallLubricationIntegral(Scalar h0, Scalar h1, Scalar a, Scalar viscosity,
                               const LubricationParameters& p) {
  return pairLubricationIntegral(h0, h1, a, std::numeric_limits<Scalar>::infinity(), viscosity, p);
}

LubricationGapLaw::LubricationGapLaw(Scalar a1, Scalar a2, Scalar viscosity, const LubricationParameters& p)
    : LubricationGapLaw(a1, a2, viscosity, p, std::isfinite(a2) ? a1 * a2 / (a1 + a2) : a1) {}

LubricationGapLaw::LubricationGapLaw(Scalar a1, Scalar a2, Scalar viscosity, const LubricationParameters& p,
                                     Scalar squeezeRadius, Scalar cellSize)
    : wall_(!std::isfinite(a2)), force_(6 * kPi * viscosity * a1), sat_(p.saturation) {
  // the leading term of lambda, A/x, is 6 pi mu a1 A/x = 6 pi mu R_s^2/h with
  // R_s the spheres' squeeze radius: scaled by (R*/R_s)^2 it is the paraboloid's
  const Scalar sphereRadius = wall_ ? a1 : a1 * a2 / (a1 + a2);
  const Scalar leading = (squeezeRadius / sphereRadius) * (squeezeRadius / sphereRadius);
  if (wall_) {
    A_ = leading;
    logB_ = 0.2;
    scale_ = 1 / a1;
  } else {
    const PairTerms t = pairTerms(a1, a2);
    A_ = leading * t.A;
    B_ = t.B;
    C_ = t.C;
    logB_ = t.B;
    scale_ = 2 / (a1 + a2);
  }
  act_ = p.activationRatio(a1, a2, cellSize);
  delta_ = p.resolvedGapRatio(a1, a2, cellSize);
  if (delta_ > 0) {
    unresolvedAct_ = unresolved(act_);
  } else {
    lambdaAct_ = lambda(act_);
  }
  correctionSat_ = correction(sat_);
  primitiveSat_ = correctionPrimitive(sat_);
}

Scalar LubricationGapLaw::unresolved(Scalar x) const {
  return A_ * (1 / x - 1 / std::hypot(x, delta_)) +
         0.5 * logB_ * std::log1p(delta_ * delta_ / (x * x));
}

Scalar LubricationGapLaw::unresolvedPrimitive(Scalar x) const {
  return A_ * (std::log(x) - std::asinh(x / delta_)) +
         0.5 * logB_ * (x * std::log1p(delta_ * delta_ / (x * x)) + 2 * delta_ * std::atan(x / delta_));
}

Scalar LubricationGapLaw::correction(Scalar x) const {
  return delta_ > 0 ? unresolved(x) - unresolvedAct_ : lambda(x) - lambdaAct_;
}

Scalar LubricationGapLaw::correctionPrimitive(Scalar x) const {
  return delta_ > 0 ? unresolvedPrimitive(x) - unresolvedAct_ * x
                    : lambdaPrimitive(x) - lambdaAct_ * x;
}

Scalar LubricationGapLaw::lambda(Scalar x) const {
  if (wall_) return wallLubricationLambda(x) + (A_ - 1) / x;
  const Scalar lnInv = -std::log(x);
  return A_ / x + B_ * lnInv + C_ * x * lnInv;
}

Scalar LubricationGapLaw::lambdaPrimitive(Scalar x) const {
  if (wall_) return wallLambdaPrimitive(x) + (A_ - 1) * std::log(x);
  return pairLambdaPrimitive(x, PairTerms{A_, B_, C_});
}

Scalar LubricationGapLaw::coefficient(Scalar gap) const {
  const Scalar x = scale_ * gap;
  if (!(x < act_) || gap < 0) return 0;
  return force_ * (x > sat_ ? correction(x) : correctionSat_);
}

Scalar LubricationGapLaw::logFactor(Scalar gap) const {
  const Scalar x = scale_ * gap;
  if (!(x < act_) || gap < 0) return 0;
  const Scalar xe = std::max(x, sat_);
  // ratio form: the flow carries ln(1/x_act); resolved-gap form: ln(1/s)
  if (delta_ > 0) {
    return 0.5 * (std::log1p(delta_ * delta_ / (xe * xe)) -
                  std::log1p(delta_ * delta_ / (act_ * act_)));
  }
  return std::log(act_ / xe);
}

Scalar LubricationGapLaw::primitive(Scalar gap) const {
  Scalar x = scale_ * gap;
  if (!(x > 0)) return 0;
  x = std::min(x, act_);
  Scalar integral = correctionSat_ * std::min(x, sat_);
  if (x > sat_) integral += correctionPrimitive(x) - primitiveSat_;
  return force_ / scale_ * integral;
}

}  // namespace collision
