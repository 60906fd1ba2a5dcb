#include "collision/LubricationLaw.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace collision;

TEST(LubricationLaw, EqualSpheresAreTheReferenceForm) {
  for (Scalar xi : {1e-4, 1e-3, 1e-2, 0.1}) {
    const Scalar ref = 1 / (4 * xi) - 9.0 / 40 * std::log(xi) - 3.0 / 112 * xi * std::log(xi);
    EXPECT_NEAR(pairLubricationLambda(xi, 0.7, 0.7), ref, 1e-12 * ref) << xi;
  }
}

TEST(LubricationLaw, LargeSecondSphereTendsToTheWall) {
  // a1 lambda_pair(xi = 2h/(a1 + a2)) -> a1 lambda_wall(h/a1) ~ a1^2/h as a2 -> infinity
  const Scalar a1 = 1, h = 1e-6, a2 = 1e4;
  const Scalar pair = pairLubricationLambda(2 * h / (a1 + a2), a1, a2);
  const Scalar wall = wallLubricationLambda(h / a1);
  // leading term beta^2/(1 + beta)^2 a1/h: off by 2 a1/a2 = 2e-4 at finite a2
  EXPECT_NEAR(pair / wall, 1 - 2 * a1 / a2, 2e-5);
}

TEST(LubricationLaw, CoefficientIsZeroBeyondActivationContinuousAtItFrozenBelowSaturationOffInContact) {
  LubricationParameters p;
  const Scalar a = 0.5, mu = 2e-3;
  // pair (equal radii: xi = h/a)
  EXPECT_EQ(pairLubricationCoefficient(p.pairActivation * a, a, a, mu, p), 0);
  EXPECT_EQ(pairLubricationCoefficient(1.0, a, a, mu, p), 0);
  EXPECT_LT(pairLubricationCoefficient(p.pairActivation * a * (1 - 1e-9), a, a, mu, p), 1e-9);
  const Scalar sat = pairLubricationCoefficient(p.saturation * a, a, a, mu, p);
  EXPECT_GT(sat, 0);
  EXPECT_EQ(pairLubricationCoefficient(0.1 * p.saturation * a, a, a, mu, p), sat);
  EXPECT_EQ(pairLubricationCoefficient(0, a, a, mu, p), sat);
  // in contact the spring-dashpot acts alone
  EXPECT_EQ(pairLubricationCoefficient(-0.2 * a, a, a, mu, p), 0);
  EXPECT_EQ(pairLubricationCoefficient(-1e-12 * a, a, a, mu, p), 0);
  EXPECT_EQ(wallLubricationCoefficient(-1e-6 * a, a, mu, p), 0);
  EXPECT_GT(wallLubricationCoefficient(0, a, mu, p), 0);
  // grows monotonically as the gap closes
  Scalar last = 0;
  for (Scalar e = p.pairActivation; e >= p.saturation; e *= 0.8) {
    const Scalar c = pairLubricationCoefficient(e * a, a, a, mu, p);
    EXPECT_GE(c, last);
    last = c;
  }
  // wall: infinite second radius
  const Scalar inf = std::numeric_limits<Scalar>::infinity();
  EXPECT_EQ(pairLubricationCoefficient(0.01 * a, a, inf, mu, p),
            wallLubricationCoefficient(0.01 * a, a, mu, p));
  EXPECT_EQ(wallLubricationCoefficient(p.wallActivation * a, a, mu, p), 0);
  const Scalar eps = 0.01;
  EXPECT_NEAR(wallLubricationCoefficient(eps * a, a, mu, p),
              6 * M_PI * mu * a * (wallLubricationLambda(eps) - wallLubricationLambda(p.wallActivation)),
              1e-14);
  // the 1/eps singularity dominates near contact: F ~ 6 pi mu a^2/h
  const Scalar small = 2e-3;
  EXPECT_NEAR(wallLubricationCoefficient(small * a, a, mu, p) / (6 * M_PI * mu * a / small), 1, 0.05);
}

TEST(LubricationLaw, BadParametersNameTheParameterAndRange) {
  LubricationParameters p;
  p.saturation = 0;
  try {
    p.validate();
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("saturation"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("(0, 1)"), std::string::npos);
  }
  p = LubricationParameters();
  p.pairActivation = p.saturation / 2;
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p = LubricationParameters();
  p.wallActivation = std::nan("");
  EXPECT_THROW(p.validate(), std::invalid_argument);
}

namespace {
// int_{h0}^{h1} c(h) dh by the composite midpoint rule, n panels between
// each of the kinks of c (contact, saturation and activation gaps)
Scalar quadrature(Scalar h0, Scalar h1, Scalar a1, Scalar a2, Scalar mu, const LubricationParameters& p,
                  const std::vector<Scalar>& kinks, int n = 100000) {
  const Scalar sign = h1 < h0 ? -1 : 1;
  std::vector<Scalar> x{std::min(h0, h1), std::max(h0, h1)};
  for (Scalar k : kinks) {
    if (k > x.front() && k < x.back()) x.push_back(k);
  }
  std::sort(x.begin(), x.end());
  Scalar sum = 0;
  for (std::size_t j = 0; j + 1 < x.size(); ++j) {
    const Scalar dh = (x[j + 1] - x[j]) / n;
    for (int i = 0; i < n; ++i) sum += pairLubricationCoefficient(x[j] + (i + 0.5) * dh, a1, a2, mu, p) * dh;
  }
  return sign * sum;
}
}  // namespace

TEST(LubricationLaw, TheIntegralOverTheGapMatchesQuadratureAndTheCoefficient) {
  // the closed form of int c dh against a fine quadrature, for a wall and two
  // sphere pairs, over paths crossing the saturation and activation gaps and
  // into contact, both directions; and (I(h, h + dh))/dh -> c(h)
  LubricationParameters p;
  const Scalar mu = 0.02, a = 2e-3;
  const Scalar inf = std::numeric_limits<Scalar>::infinity();
  for (Scalar a2 : {inf, a, 2.5 * a}) {
    const Scalar act = (std::isinf(a2) ? p.wallActivation * a : 0.5 * p.pairActivation * (a + a2));
    const Scalar sat = act / (std::isinf(a2) ? p.wallActivation : p.pairActivation) * p.saturation;
    for (auto [h0, h1] : {std::pair<Scalar, Scalar>{2 * act, -0.1 * a}, {0.9 * act, 0.5 * sat},
                          {0.3 * sat, 0.7 * act}, {-0.01 * a, 3 * sat}, {0.5 * act, 0.2 * act}}) {
      const Scalar exact = pairLubricationIntegral(h0, h1, a, a2, mu, p);
      const Scalar numeric = quadrature(h0, h1, a, a2, mu, p, {0, sat, act});
      EXPECT_NEAR(exact, numeric, 1e-6 * std::abs(numeric)) << a2 << " " << h0 << " " << h1;
      EXPECT_EQ(exact, -pairLubricationIntegral(h1, h0, a, a2, mu, p));
    }
    for (Scalar h : {0.5 * sat, 2 * sat, 0.1 * act, 0.9 * act}) {
      const Scalar dh = 1e-7 * h;
      EXPECT_NEAR(pairLubricationIntegral(h, h + dh, a, a2, mu, p) / dh,
                  pairLubricationCoefficient(h + 0.5 * dh, a, a2, mu, p),
                  1e-6 * pairLubricationCoefficient(h, a, a2, mu, p))
          << a2 << " " << h;
    }
    EXPECT_EQ(pairLubricationIntegral(-0.2 * a, -0.01 * a, a, a2, mu, p), 0) << "none in contact";
    EXPECT_EQ(pairLubricationIntegral(1.5 * act, 3 * act, a, a2, mu, p), 0) << "none beyond activation";
  }
  // the wall form through the pair function with an infinite second radius
  EXPECT_EQ(pairLubricationIntegral(1e-4, 1e-6, a, inf, mu, p), wallLubricationIntegral(1e-4, 1e-6, a, mu, p));
}

TEST(LubricationLaw, TheResolvedGapIsCellsOfTheCellSizeAsARatioOfTheRadii) {
  const Scalar inf = std::numeric_limits<Scalar>::infinity();
  LubricationParameters p;
  p.wallResolvedGapCells = 0.6;
  p.pairResolvedGapCells = 1.5;
  const Scalar a = 0.5, cell = 1.0 / 64, k = LubricationParameters::kActivationOverResolvedGap;
  EXPECT_TRUE(p.resolvedGapForm(true));
  EXPECT_DOUBLE_EQ(p.resolvedGapRatio(a, inf, cell), 0.6 * cell / a);
  EXPECT_DOUBLE_EQ(p.activationRatio(a, inf, cell), k * 0.6 * cell / a);
  EXPECT_DOUBLE_EQ(p.activationGap(a, inf, cell), k * 0.6 * cell);
  EXPECT_DOUBLE_EQ(p.resolvedGapRatio(a, 2 * a, cell), 2 * 1.5 * cell / (3 * a));
  EXPECT_DOUBLE_EQ(p.activationGap(a, 2 * a, cell), k * 1.5 * cell);
  // the activation at most the laws' range, at least the saturation ratio
  EXPECT_EQ(p.activationRatio(0.01 * cell, inf, cell), LubricationParameters::kMaxActivation);
  EXPECT_EQ(p.activationRatio(1e6 * cell, inf, cell), p.saturation);
  // a side given 0 cells keeps the ratio form
  p.pairResolvedGapCells = 0;
  EXPECT_FALSE(p.resolvedGapForm(false));
  EXPECT_EQ(p.resolvedGapRatio(a, a, cell), 0);
  EXPECT_EQ(p.activationRatio(a, a, cell), p.pairActivation);
  EXPECT_EQ(p.activationRatio(a, a, 0), p.pairActivation);
  // the resolved-gap form needs the cell size
  try {
    p.activationRatio(a, inf, 0);
    FAIL() << "no cell size accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("wallResolvedGapCells"), std::string::npos) << e.what();
  }
  p.wallResolvedGapCells = -1;
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p.wallResolvedGapCells = 9;
  EXPECT_THROW(p.validate(), std::invalid_argument);
}

TEST(LubricationLaw, TheResolvedGapFormAddsWhatTheGapWidenedInQuadratureLacks) {
  // wall (A = 1, B = 1/5): c = 6 pi mu a [u(x) - u(x_act)] with
  // u(x) = 1/x - 1/s + (1/10) ln(1 + x_d^2/x^2), s = sqrt(x^2 + x_d^2), so that
  // the flow's lambda at the widened gap s plus the correction is lambda at x
  // up to the C term and the shift at x_act
  const Scalar inf = std::numeric_limits<Scalar>::infinity();
  LubricationParameters p;
  p.wallResolvedGapCells = 0.6;
  const Scalar a = 0.5, mu = 2e-3, cell = 1.0 / 8;
  const Scalar xd = 0.6 * cell / a, xAct = 4 * xd;
  const LubricationGapLaw law(a, inf, mu, p, a, cell);
  const auto u = [&](Scalar x) {
    return 1 / x - 1 / std::hypot(x, xd) + 0.1 * std::log1p(xd * xd / (x * x));
  };
  EXPECT_EQ(law.coefficient(xAct * a), 0);
  EXPECT_EQ(law.coefficient(1.01 * xAct * a), 0);
  EXPECT_LT(law.coefficient(0.999999 * xAct * a), 1e-6 * law.coefficient(0.5 * xAct * a));
  for (const Scalar x : {0.9 * xAct, 0.3 * xAct, 0.01, 0.002}) {
    const Scalar expected = 6 * kPi * mu * a * (u(x) - u(xAct));
    EXPECT_NEAR(law.coefficient(x * a), expected, 1e-12 * expected) << x;
    // the flow's lambda at s plus the correction (before the shift) is lambda at x
    const Scalar s = std::hypot(x, xd);
    const Scalar cTerm = x * std::log(x) / 21 - s * std::log(s) / 21;
    EXPECT_NEAR(wallLubricationLambda(s) + u(x), wallLubricationLambda(x) + cTerm, 1e-12 / x) << x;
    EXPECT_NEAR(law.logFactor(x * a),
                0.5 * (std::log1p(xd * xd / (x * x)) - std::log1p(xd * xd / (xAct * xAct))), 1e-12);
  }
  // frozen below the saturation gap, off in contact and beyond the activation gap
  EXPECT_EQ(law.coefficient(1e-4 * a), law.coefficient(p.saturation * a));
  EXPECT_EQ(law.coefficient(-1e-6), 0);
  EXPECT_EQ(law.logFactor(xAct * a), 0);
  // the primitive against a midpoint quadrature of the coefficient, across
  // the saturation and activation gaps
  for (auto [h0, h1] : {std::pair<Scalar, Scalar>{2 * xAct * a, 0.2 * p.saturation * a},
                        {0.5 * xAct * a, 0.3 * xAct * a}}) {
    const int n = 400000;
    Scalar sum = 0;
    const Scalar dh = (h1 - h0) / n;
    for (int i = 0; i < n; ++i) sum += law.coefficient(h0 + (i + 0.5) * dh) * dh;
    EXPECT_NEAR(law.primitive(h1) - law.primitive(h0), sum, 1e-6 * std::abs(sum)) << h0 << " " << h1;
  }
  // a resolved gap whose activation falls under the saturation gap: no law
  const LubricationGapLaw none(1e4 * cell, inf, mu, p, 1e4 * cell, cell);
  EXPECT_EQ(none.coefficient(0), 0);
  EXPECT_EQ(none.primitive(0.5 * cell), 0);
  EXPECT_EQ(none.logFactor(0), 0);
}
