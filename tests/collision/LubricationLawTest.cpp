#include "collision/LubricationLaw.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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
