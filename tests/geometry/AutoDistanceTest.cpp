// auto: the table picks the method, the stop is always certified, and a
// failing choice falls back to another method.
#include "ellipsoids/AutoDistance.hpp"
#include "TestGeometry.hpp"

#include <gtest/gtest.h>

#include <limits>

using namespace ellipsoids;
using namespace testgeometry;

TEST(AutoDistance, PaperTablePicksGjkForElongatedAndMovingBallsOtherwise) {
  const AutoDistance paper(AutoDistance::paperTable());
  const Ellipsoid s = Ellipsoid::sphere(1, Vec3::Zero());
  for (Scalar ar : {1.0 / 6, 1.0 / 3, 3.0, 6.0}) {
    const Ellipsoid e = Ellipsoid::spheroid(ar, 1, Vec3(5, 0, 0), Quat::Identity());
    EXPECT_EQ(paper.choose(s, e, 1e-6).name(), "gjk") << ar;
  }
  for (Scalar ar : {2.0 / 3, 1.0, 1.5, 2.9}) {
    const Ellipsoid e = Ellipsoid::spheroid(ar, 1, Vec3(5, 0, 0), Quat::Identity());
    EXPECT_EQ(paper.choose(s, e, 1e-6).name(), "movingBalls") << ar;
  }
}

TEST(AutoDistance, DefaultTablePicksPerItsRows) {
  const AutoDistance a;
  const auto table = AutoDistance::defaultTable();
  const Ellipsoid s = Ellipsoid::sphere(1, Vec3::Zero());
  for (Scalar ar : {0.1, 1.0 / 6, 0.5, 1.0, 2.0, 6.0, 10.0}) {
    for (Scalar relEps : {1e-3, 1e-5, 1e-8}) {
      const Ellipsoid e = Ellipsoid::spheroid(ar, 2, Vec3(5, 0, 0), Quat::Identity());
      const Scalar elongation = std::max(ar, 1 / ar);
      const Scalar epsD = relEps * std::min(s.equivalentRadius(), e.equivalentRadius());
      std::string expected;
      for (const auto& row : table) {
        if (elongation <= row.maxElongation && relEps <= row.maxRelativeEps * (1 + 1e-12)) {
          expected = row.method;
          break;
        }
      }
      EXPECT_EQ(a.choose(s, e, epsD).name(), expected) << ar << " " << relEps;
    }
  }
}

TEST(AutoDistance, DefaultPicksTheMeasuredFastestMethodOnTheBenchmarkGrid) {
  // docs/benchmarks.md: the dual method was fastest in every (Ar, eps_d) cell
  const AutoDistance a;
  for (Scalar ar1 : {1.0 / 6, 1.0 / 3, 2.0 / 3, 1.5, 3.0, 6.0}) {
    for (Scalar ar2 : {1.0 / 6, 1.0, 6.0}) {
      for (Scalar relEps = 1e-3; relEps > 0.9e-8; relEps /= 10) {
        const Ellipsoid e1 = Ellipsoid::spheroid(ar1, 0.7, Vec3::Zero(), Quat::Identity());
        const Ellipsoid e2 = Ellipsoid::spheroid(ar2, 1.3, Vec3(5, 0, 0), Quat::Identity());
        const Scalar epsD = relEps * std::min(e1.equivalentRadius(), e2.equivalentRadius());
        EXPECT_EQ(a.choose(e1, e2, epsD).name(), "dual") << ar1 << " " << ar2 << " " << relEps;
      }
    }
  }
}

TEST(AutoDistance, FallsBackWhenTheChosenMethodFails) {
  // a table that always picks Jain et al. with a tiny step: it cannot converge
  // in the iteration limit; auto still returns a certified answer
  const Scalar inf = std::numeric_limits<Scalar>::infinity();
  const AutoDistance a({{inf, inf, "jain"}});
  const MirrorCase m = mirrorCase(3, 1e-4, 1);
  DistanceOptions o;
  o.epsD = 1e-9;
  o.maxIterations = 50;
  const DistanceResult r = a.distance(m.e1, m.e2, o);
  EXPECT_EQ(r.status, DistanceStatus::converged);
  EXPECT_LE(r.bracketWidth(), 1e-9);
  EXPECT_LE(r.lower, m.exactDistance);
  EXPECT_GE(r.upper, m.exactDistance);
}

TEST(AutoDistance, OverlapIsUnsigned) {
  const AutoDistance a;
  DistanceOptions o;
  const DistanceResult r = a.distance(Ellipsoid::sphere(1, Vec3::Zero()),
                                      Ellipsoid::sphere(1, Vec3(1, 0, 0)), o);
  EXPECT_EQ(r.status, DistanceStatus::overlapping);
  EXPECT_EQ(r.distance, 0);
  EXPECT_EQ(r.lower, 0);
  EXPECT_EQ(r.upper, 0);
}

TEST(AutoDistance, RejectsBadTables) {
  EXPECT_THROW(AutoDistance(std::vector<AutoDistance::Rule>{}), std::invalid_argument);
  EXPECT_THROW(AutoDistance({{1, 1, "nope"}}), std::invalid_argument);
  EXPECT_THROW(AutoDistance({{1, 1, "auto"}}), std::invalid_argument);
}
