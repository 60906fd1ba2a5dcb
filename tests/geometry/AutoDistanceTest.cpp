// auto: the table picks the method, the stop is always certified, and a
// failing choice falls back to another method.
#include "ellipsoids/AutoDistance.hpp"
#include "ellipsoids/DistanceMethod.hpp"
#include "TestGeometry.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <random>

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

TEST(AutoDistance, ACustomTableIsFollowedRowByRow) {
  // rows by elongation, then by accuracy: each pair's expected method written out
  const Scalar inf = std::numeric_limits<Scalar>::infinity();
  const AutoDistance a({{2, 1e-6, "gjk"}, {2, inf, "movingBalls"}, {5, inf, "dual"}, {inf, inf, "jain"}});
  const Ellipsoid s = Ellipsoid::sphere(1, Vec3::Zero());
  const struct {
    Scalar ar;      // of body 2
    Scalar relEps;  // eps_d / R_eq of the sphere
    const char* expected;
  } cases[] = {{1.5, 1e-8, "gjk"},  {1 / 1.5, 1e-7, "gjk"}, {1.5, 1e-5, "movingBalls"}, {1.9, 1e-3, "movingBalls"},
               {3.0, 1e-8, "dual"}, {1 / 4.5, 1e-3, "dual"}, {6.0, 1e-8, "jain"},          {1.0 / 10, 1, "jain"}};
  for (const auto& c : cases) {
    const Ellipsoid e = Ellipsoid::spheroid(c.ar, 2, Vec3(5, 0, 0), Quat::Identity());
    EXPECT_EQ(a.choose(s, e, c.relEps).name(), c.expected) << "Ar " << c.ar << ", eps " << c.relEps;
  }
}

TEST(AutoDistance, AnswersWithTheMethodItChooses) {
  // the chosen method really runs: auto's answer is that method's certified
  // answer, bit for bit (the default table's dual; a one-row table's GJK)
  const Scalar inf = std::numeric_limits<Scalar>::infinity();
  const AutoDistance byDefault;
  const AutoDistance byGjk({{inf, inf, "gjk"}});
  const auto dual = makeDistanceMethod("dual");
  const auto gjk = makeDistanceMethod("gjk");
  std::mt19937_64 rng(61);
  DistanceOptions o;
  o.epsD = 1e-7;
  o.stopRule = StopRule::certified;
  for (int k = 0; k < 200; ++k) {
    const Ellipsoid e1 = randomEllipsoid(rng, 0.1, 2, 1);
    const Ellipsoid e2 = movedTo(randomEllipsoid(rng, 0.1, 2, 0), Vec3(8, 0, 0) + randomUnit(rng));
    for (const auto& [autoMethod, single] :
         {std::make_pair(&byDefault, dual.get()), std::make_pair(&byGjk, gjk.get())}) {
      const DistanceResult a = autoMethod->distance(e1, e2, o);
      const DistanceResult m = single->distance(e1, e2, o);
      ASSERT_EQ(m.status, DistanceStatus::converged) << single->name() << " " << k;
      EXPECT_EQ(a.distance, m.distance) << single->name() << " " << k;
      EXPECT_EQ(a.iterations, m.iterations) << single->name() << " " << k;
      EXPECT_EQ(a.lower, m.lower) << single->name() << " " << k;
    }
  }
}

TEST(AutoDistance, FallsBackWhenTheChosenMethodFails) {
  // a table that always picks Jain et al. with a tiny step: it cannot converge
  // in the iteration limit; auto then answers with the first fallback, the
  // dual method, and counts both methods' iterations
  const Scalar inf = std::numeric_limits<Scalar>::infinity();
  const AutoDistance a({{inf, inf, "jain"}});
  const MirrorCase m = mirrorCase(3, 1e-4, 1);
  DistanceOptions o;
  o.epsD = 1e-9;
  o.maxIterations = 50;
  DistanceOptions certified = o;
  certified.stopRule = StopRule::certified;
  const DistanceResult jain = makeDistanceMethod("jain")->distance(m.e1, m.e2, certified);
  ASSERT_NE(jain.status, DistanceStatus::converged);  // the chosen method does fail
  const DistanceResult dual = makeDistanceMethod("dual")->distance(m.e1, m.e2, certified);
  const DistanceResult r = a.distance(m.e1, m.e2, o);
  EXPECT_EQ(r.status, DistanceStatus::converged);
  EXPECT_EQ(r.distance, dual.distance);  // the fallback's answer
  EXPECT_EQ(r.upper, dual.upper);
  EXPECT_EQ(r.iterations, jain.iterations + dual.iterations);
  EXPECT_LE(r.bracketWidth(), 1e-9);
  EXPECT_LE(r.lower, m.exactDistance);
  EXPECT_GE(r.upper, m.exactDistance);
}

TEST(AutoDistance, PaperIsTheFoundingPapersDispatchWithItsOwnFallback) {
  const auto paper = makeDistanceMethod("paper");
  EXPECT_EQ(paper->name(), "paper");
  EXPECT_FALSE(paper->isSigned());
  const auto& chooser = dynamic_cast<const AutoDistance&>(*paper);
  const Ellipsoid s = Ellipsoid::sphere(1, Vec3::Zero());
  for (Scalar ar : {1.0 / 6, 1.0 / 3, 3.0, 6.0}) {
    EXPECT_EQ(chooser.choose(s, Ellipsoid::spheroid(ar, 1, Vec3(5, 0, 0), Quat::Identity()), 1e-6).name(), "gjk");
  }
  for (Scalar ar : {0.34, 2.0 / 3, 1.0, 1.5, 2.9}) {
    EXPECT_EQ(chooser.choose(s, Ellipsoid::spheroid(ar, 1, Vec3(5, 0, 0), Quat::Identity()), 1e-6).name(),
              "movingBalls");
  }
  // its answer is Moving Balls' (certified stop) near Ar 1, GJK's beyond
  DistanceOptions o;
  o.epsD = 1e-8;
  o.stopRule = StopRule::certified;
  for (const auto& [ar, method] : {std::make_pair(1.5, "movingBalls"), std::make_pair(6.0, "gjk")}) {
    const MirrorCase m = mirrorCase(ar, 1e-3, 1);
    const DistanceResult p = paper->distance(m.e1, m.e2, o);
    const DistanceResult single = makeDistanceMethod(method)->distance(m.e1, m.e2, o);
    EXPECT_EQ(p.distance, single.distance) << method;
    EXPECT_EQ(p.iterations, single.iterations) << method;
  }
  // its fallback is the paper's other method, not the dual: Moving Balls
  // stopped after 3 iterations, GJK answers (the centre line solves the mirror case at once)
  o.maxIterations = 3;
  const MirrorCase m = mirrorCase(1.5, 1e-3, 1);
  const DistanceResult mb = makeDistanceMethod("movingBalls")->distance(m.e1, m.e2, o);
  ASSERT_NE(mb.status, DistanceStatus::converged);
  const DistanceResult gjk = makeDistanceMethod("gjk")->distance(m.e1, m.e2, o);
  ASSERT_EQ(gjk.status, DistanceStatus::converged);
  const DistanceResult p = paper->distance(m.e1, m.e2, o);
  EXPECT_EQ(p.distance, gjk.distance);
  EXPECT_EQ(p.iterations, mb.iterations + gjk.iterations);
  EXPECT_THROW(AutoDistance(AutoDistance::paperTable(), "x", {"paper"}), std::invalid_argument);
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
