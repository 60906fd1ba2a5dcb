// The paper's analytic validation grid (section 3): every method on the
// mirror case over Lambda x d* x Ar x eps_d. Moving Balls, GJK (from eq. 3.3),
// dual and auto meet |d - d*| <= eps_d everywhere and are scale invariant;
// every method's bracket contains d*; Newton-Coulomb, exterior penalty and
// Jain et al. terminate with a reported status.
#include "MirrorCase.hpp"

#include "ellipsoids/DistanceMethod.hpp"
#include "ellipsoids/JainDistance.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <tuple>

using namespace ellipsoids;

namespace {

const double kLambdas[] = {1e-6, 1e-3, 1, 1e3, 1e6};
const double kDistances[] = {1, 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
const double kAspectRatios[] = {1.0 / 6, 1.0 / 3, 2.0 / 3, 1.5, 3, 6};
const double kEpsRel[] = {1e-4, 1e-6, 1e-8};

struct MirrorRun {
  DistanceResult result;
  mirror::Case c;
};

MirrorRun run(const DistanceMethod& m, double lambda, double ar, double d, double eps, bool eq33) {
  MirrorRun r{DistanceResult{}, mirror::make(ar, d * lambda, lambda)};
  DistanceOptions o;
  o.epsD = eps * lambda;
  if (eq33) {
    o.useInitialDirection = true;
    o.initialDirection = mirror::eq33Direction(r.c);
  }
  r.result = m.distance(r.c.e1, r.c.e2, o);
  return r;
}

}  // namespace

class MirrorGridAccurate : public ::testing::TestWithParam<std::tuple<std::string, bool>> {};

TEST_P(MirrorGridAccurate, MeetsToleranceEverywhereAndIsScaleInvariant) {
  const auto method = makeDistanceMethod(std::get<0>(GetParam()));
  const bool eq33 = std::get<1>(GetParam());
  for (double ar : kAspectRatios) {
    for (double d : kDistances) {
      for (double eps : kEpsRel) {
        std::map<double, double> relError;
        for (double lambda : kLambdas) {
          const MirrorRun r = run(*method, lambda, ar, d, eps, eq33);
          const std::string where = "Lambda " + std::to_string(lambda) + " Ar " + std::to_string(ar) +
                                    " d " + std::to_string(d) + " eps " + std::to_string(eps);
          ASSERT_EQ(r.result.status, DistanceStatus::converged) << where;
          const double err = std::abs(r.result.distance - r.c.exactDistance);
          EXPECT_LE(err, eps * lambda) << where;
          EXPECT_LE(r.result.lower, r.c.exactDistance) << where;
          EXPECT_GE(r.result.upper, r.c.exactDistance) << where;
          relError[lambda] = (r.result.distance - r.c.exactDistance) / lambda;
        }
        // scale invariance: the relative error does not depend on Lambda
        for (const auto& [lambda, e] : relError) {
          EXPECT_NEAR(e, relError[1], 1e-3 * eps + 1e-13)
              << "Lambda " << lambda << " Ar " << ar << " d " << d << " eps " << eps;
        }
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Methods, MirrorGridAccurate,
    ::testing::Values(std::make_tuple("movingBalls", false), std::make_tuple("gjk", true),
                      std::make_tuple("dual", false), std::make_tuple("dual", true),
                      std::make_tuple("auto", false)),
    [](const ::testing::TestParamInfo<std::tuple<std::string, bool>>& info) {
      return std::get<0>(info.param) + (std::get<1>(info.param) ? "FromEq33" : "");
    });

class MirrorGridFragile : public ::testing::TestWithParam<std::string> {};

TEST_P(MirrorGridFragile, TerminatesWithAValidBracket) {
  const auto method = makeDistanceMethod(GetParam());
  int converged = 0, total = 0;
  for (double lambda : kLambdas) {
    for (double ar : kAspectRatios) {
      for (double d : kDistances) {
        for (double eps : kEpsRel) {
          const MirrorRun r = run(*method, lambda, ar, d, eps, false);
          const std::string where = "Lambda " + std::to_string(lambda) + " Ar " + std::to_string(ar) +
                                    " d " + std::to_string(d) + " eps " + std::to_string(eps);
          ++total;
          converged += r.result.status == DistanceStatus::converged;
          EXPECT_NE(r.result.status, DistanceStatus::overlapping) << where;
          EXPECT_TRUE(std::isfinite(r.result.distance)) << where;
          EXPECT_LE(r.result.lower, r.c.exactDistance) << where;
          EXPECT_GE(r.result.upper, r.c.exactDistance) << where;
          EXPECT_LE(r.result.iterations, 100000) << where;
        }
      }
    }
  }
  EXPECT_GT(converged, 0);
  std::cout << GetParam() << ": " << converged << " of " << total << " converged\n";
}

INSTANTIATE_TEST_SUITE_P(Methods, MirrorGridFragile,
                         ::testing::Values("newtonCoulomb", "exteriorPenalty", "jain"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });
