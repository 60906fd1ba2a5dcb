// The dual Newton method: signed form (penetration depth), warm start,
// iteration counts, spurious maxima.
#include "ellipsoids/DualNewton.hpp"
#include "ellipsoids/OverlapTest.hpp"
#include "TestGeometry.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

using namespace ellipsoids;
using namespace testgeometry;

namespace {
DistanceOptions eps(Scalar e) {
  DistanceOptions o;
  o.epsD = e;
  return o;
}
}  // namespace

TEST(DualNewton, SignedDistanceOfOverlappingSpheresIsMinusTheDepth) {
  const DualNewton dual;
  std::mt19937_64 rng(41);
  for (Scalar d : {1.4, 1.0, 0.5, 0.1}) {  // centre distance; radii 1 and 0.5
    const Vec3 n = randomUnit(rng);
    const Ellipsoid s1 = Ellipsoid::sphere(1, Vec3(1, 1, 1));
    const Ellipsoid s2 = Ellipsoid::sphere(0.5, s1.centre() + d * n);
    const DistanceResult r = dual.distance(s1, s2, eps(1e-10));
    EXPECT_EQ(r.status, DistanceStatus::overlapping);
    EXPECT_NEAR(r.distance, d - 1.5, 1e-9);
    EXPECT_LE(r.lower, d - 1.5);
    EXPECT_GE(r.upper, d - 1.5);
    EXPECT_LE(r.upper, 0);
    EXPECT_LT((r.direction - n).norm(), 1e-6);
  }
}

TEST(DualNewton, PenetrationDepthOfASpheroidAndASphereAlongTheAxis) {
  // prolate a = 2, b = 1 along x, sphere R = 0.5 on the axis at distance d:
  // pushing along the axis needs a + R - d < b + R (sideways) when d > a - b
  const DualNewton dual;
  const Ellipsoid e(Vec3(2, 1, 1), Vec3::Zero(), Quat::Identity());
  for (Scalar d : {2.4, 2.2, 1.8}) {
    const DistanceResult r = dual.distance(e, Ellipsoid::sphere(0.5, Vec3(d, 0, 0)), eps(1e-10));
    EXPECT_EQ(r.status, DistanceStatus::overlapping);
    EXPECT_NEAR(r.distance, d - 2.5, 1e-9) << "d " << d;
    EXPECT_NEAR(r.direction.x(), 1, 1e-6);
  }
}

namespace {

/// max over unit n of L(n) by brute force: a Fibonacci sphere, then random refinement.
Scalar bruteForceMaxL(const Ellipsoid& e1, const Ellipsoid& e2, std::mt19937_64& rng) {
  const Vec3 dr = e2.centre() - e1.centre();
  auto L = [&](const Vec3& n) { return n.dot(dr) - e1.supportRadius(n) - e2.supportRadius(n); };
  Scalar best = -1e300;
  Vec3 bestN = Vec3::UnitX();
  const int m = 20000;
  for (int i = 0; i < m; ++i) {
    const Scalar z = 1 - 2 * (i + 0.5) / m, r = std::sqrt(1 - z * z), phi = i * 2.399963229728653;
    const Vec3 n(r * std::cos(phi), r * std::sin(phi), z);
    if (L(n) > best) {
      best = L(n);
      bestN = n;
    }
  }
  std::normal_distribution<Scalar> g;
  for (Scalar radius = 0.05; radius > 1e-9; radius *= 0.7) {
    for (int k = 0; k < 60; ++k) {
      const Vec3 n = (bestN + radius * Vec3(g(rng), g(rng), g(rng))).normalized();
      if (L(n) > best) {
        best = L(n);
        bestN = n;
      }
    }
  }
  return best;
}

}  // namespace

TEST(DualNewton, PenetrationDepthMatchesBruteForce) {
  const DualNewton dual;
  std::mt19937_64 rng(44);
  for (int k = 0; k < 60; ++k) {
    const Ellipsoid e1 = randomEllipsoid(rng, 0.2, 2, 0);
    const Ellipsoid shape = randomEllipsoid(rng, 0.2, 2, 0);
    const Vec3 n = randomUnit(rng);
    // overlaps from slight to deep
    const Scalar overlap = std::pow(10.0, -3 + 3 * (k % 4) / 3.0) * shape.minSemiAxis();
    const Ellipsoid e2 = tangentPartner(e1, shape.semiAxes(), shape.orientation(), n, -overlap);
    const DistanceResult r = dual.distance(e1, e2, eps(1e-10));
    const Scalar brute = bruteForceMaxL(e1, e2, rng);
    EXPECT_EQ(r.status, DistanceStatus::overlapping) << k;
    EXPECT_GE(r.distance, brute - 1e-9) << k;   // at least as good as sampling
    EXPECT_LE(r.distance, brute + 1e-6) << k;   // and sampling is close to it
    EXPECT_LE(r.lower, r.distance);
    EXPECT_LE(r.upper, 0);
  }
}

TEST(DualNewton, SignMatchesTheOverlapTestOnNearTangentPairs) {
  // gaps of +-1e-9 of the size: the sign of the dual distance and the exact
  // algebraic test agree
  const DualNewton dual;
  const JiaOverlapTest jia;
  std::mt19937_64 rng(42);
  for (int k = 0; k < 1000; ++k) {
    const Ellipsoid e1 = randomEllipsoid(rng, 0.1, 2, 1);
    std::uniform_real_distribution<Scalar> u(0.1, 2);
    const Vec3 ax2(u(rng), u(rng), u(rng));
    const Vec3 n = randomUnit(rng);
    const Scalar size = std::max(e1.maxSemiAxis(), ax2.maxCoeff());
    for (Scalar gap : {1e-9, -1e-9}) {
      const Ellipsoid e2 = tangentPartner(e1, ax2, randomRotation(rng), n, gap * size);
      const DistanceResult r = dual.distance(e1, e2, eps(1e-12 * size));
      const OverlapStatus o = jia.test(e1, e2);
      if (gap > 0) {
        EXPECT_EQ(o, OverlapStatus::separated) << k;
        EXPECT_EQ(r.status, DistanceStatus::converged) << k;
        EXPECT_GT(r.lower, 0) << k;
        EXPECT_NEAR(r.distance, gap * size, 2e-12 * size) << k;
      } else {
        EXPECT_EQ(o, OverlapStatus::overlapping) << k;
        EXPECT_EQ(r.status, DistanceStatus::overlapping) << k;
        EXPECT_LT(r.distance, 0) << k;
        EXPECT_NEAR(r.distance, gap * size, 2e-12 * size) << k;
      }
    }
  }
}

TEST(DualNewton, FewIterationsAndWarmStartHelps) {
  const DualNewton dual;
  std::mt19937_64 rng(43);
  long cold = 0, warm = 0;
  int n = 0;
  for (int k = 0; k < 500; ++k) {
    const Ellipsoid e1 = Ellipsoid::spheroid(3, 1, Vec3::Zero(), randomRotation(rng));
    const Ellipsoid e2 = Ellipsoid::spheroid(3, 1, 1.8 * randomUnit(rng), randomRotation(rng));
    if (JiaOverlapTest().test(e1, e2) != OverlapStatus::separated) continue;
    DistanceOptions o = eps(1e-5 * e1.minGaussianRadius());
    const DistanceResult r = dual.distance(e1, e2, o);
    ASSERT_EQ(r.status, DistanceStatus::converged);
    EXPECT_LE(r.iterations, 15);
    cold += r.iterations;
    // a slightly moved pair started from the previous direction
    const Quat dq(Eigen::AngleAxis<Scalar>(0.01, randomUnit(rng)));
    const Ellipsoid e2moved(e2.semiAxes(), e2.centre() + 0.005 * randomUnit(rng), dq * e2.orientation());
    o.useInitialDirection = true;
    o.initialDirection = r.direction;
    const DistanceResult w = dual.distance(e1, e2moved, o);
    if (w.status == DistanceStatus::converged) {
      warm += w.iterations;
      ++n;
    }
  }
  ASSERT_GT(n, 100);
  EXPECT_LT(warm, cold);
}

TEST(DualNewton, ColdStartIsNearlyExactForIdenticalParallelBodies) {
  // E1 + (-E2) of two equal, equally oriented ellipsoids is the ellipsoid 2E1,
  // so the cold start (the normal of an ellipsoid enclosing the sum, at the
  // crossing of the centre line) is the answer's direction up to O(gap /
  // curvature radius): at a gap of 1e-6 at most one Newton step to 1e-8,
  // where the centre line itself needs more.
  const DualNewton dual;
  std::mt19937_64 rng(47);
  long cold = 0, centreLine = 0;
  for (int k = 0; k < 50; ++k) {
    const Quat q = randomRotation(rng);
    for (Scalar ar : {1.0 / 6, 6.0}) {
      const Ellipsoid e1 = Ellipsoid::spheroid(ar, 1, Vec3::Zero(), q);
      const Vec3 u = randomUnit(rng);
      // t u on the surface of 2 E1 (x^T (4 P)^-1 x = 1), plus the gap
      const Scalar touching = 2 / std::sqrt(u.dot(e1.shapeMatrix().inverse() * u));
      const Ellipsoid e2 = Ellipsoid::spheroid(ar, 1, (touching + 1e-6) * u, q);
      DistanceOptions o = eps(1e-8);
      const DistanceResult r = dual.distance(e1, e2, o);
      ASSERT_EQ(r.status, DistanceStatus::converged);
      EXPECT_LE(r.iterations, 1) << "Ar " << ar << " k " << k;
      EXPECT_GT(r.distance, 0);
      EXPECT_LE(r.distance, 1e-6 + 1e-12);
      cold += r.iterations;
      o.useInitialDirection = true;
      o.initialDirection = u;
      const DistanceResult c = dual.distance(e1, e2, o);
      ASSERT_EQ(c.status, DistanceStatus::converged);
      EXPECT_NEAR(c.distance, r.distance, 1e-8);
      centreLine += c.iterations;
    }
  }
  EXPECT_LT(2 * cold, centreLine) << "cold " << cold << ", from the centre line " << centreLine;
}

TEST(DualNewton, ColdStartOfDistantElongatedPairsLeansTowardsTheCentreLine) {
  // Far apart, the normal of the answer tends to the centre line, not to the
  // normal where the centre line crosses the enclosing ellipsoid: the start
  // shifts M by the gap (M + t I). Random Ar 6 and Ar 1/6 pairs 0.5 to 4
  // D_eq apart: fewer than 1.75 Newton steps per pair at 1e-5 D_eq on average
  // (1.1 and 1.5 with the shift; without it 2.1 and 2.7).
  const DualNewton dual;
  std::mt19937_64 rng(53);
  std::uniform_real_distribution<Scalar> centreDistance(2, 8);
  for (Scalar ar : {1.0 / 6, 6.0}) {
    long iterations = 0, pairs = 0;
    for (int attempt = 0; attempt < 100000 && pairs < 400; ++attempt) {
      const Ellipsoid e1 = Ellipsoid::spheroid(ar, 1, Vec3::Zero(), randomRotation(rng));
      const Ellipsoid e2 = Ellipsoid::spheroid(ar, 1, centreDistance(rng) * randomUnit(rng), randomRotation(rng));
      const DistanceResult r = dual.distance(e1, e2, eps(1e-5));
      if (r.status != DistanceStatus::converged || r.distance < 0.5 || r.distance > 4) continue;
      EXPECT_LE(r.bracketWidth(), 1e-5);
      iterations += r.iterations;
      ++pairs;
    }
    ASSERT_EQ(pairs, 400) << "Ar " << ar << ": too few pairs in range";
    EXPECT_LT(4 * iterations, 7 * pairs) << "Ar " << ar << ": " << iterations << " Newton steps for " << pairs
                                     << " pairs";
  }
}

TEST(DualNewton, BracketNeverExceedsTheToleranceFarFromTheOrigin) {
  // centres at 1e6: the rounding of the absolute closest points (~5e-9 here)
  // is half the tolerance; the stopping test must leave room for it (it did
  // not: brackets of eps_d plus a rounding made auto fall back to GJK)
  const DualNewton dual;
  std::mt19937_64 rng(53);
  int converged = 0;
  for (int k = 0; k < 400; ++k) {
    const Vec3 base = Vec3::Constant(1e6);
    const Ellipsoid e1 = Ellipsoid::spheroid(k % 2 ? 6.0 : 1.0 / 6, 1, base, randomRotation(rng));
    const Ellipsoid e2 = Ellipsoid::spheroid(k % 2 ? 6.0 : 1.0 / 6, 1, base + 1.6 * randomUnit(rng),
                                             randomRotation(rng));
    if (JiaOverlapTest().test(e1, e2) != OverlapStatus::separated) continue;
    const DistanceResult r = dual.distance(e1, e2, eps(1e-8));
    ASSERT_EQ(r.status, DistanceStatus::converged) << k;
    EXPECT_LE(r.bracketWidth(), 1e-8) << k;
    ++converged;
  }
  ASSERT_GT(converged, 100);
}

TEST(DualNewton, ConcentricBodiesAreOverlappingWithTheThinnestDirection) {
  const DualNewton dual;
  const Ellipsoid e1(Vec3(3, 2, 1), Vec3::Zero(), Quat::Identity());
  const Ellipsoid e2(Vec3(1.5, 1, 0.5), Vec3::Zero(), Quat::Identity());
  const DistanceResult r = dual.distance(e1, e2, eps(1e-10));
  EXPECT_EQ(r.status, DistanceStatus::overlapping);
  EXPECT_NEAR(r.distance, -1.5, 1e-9);  // separate along z: 1 + 0.5
  EXPECT_NEAR(std::abs(r.direction.z()), 1, 1e-6);
}

// Configurations that once failed, with their numbers written out (17 digits).
TEST(DualNewtonRegression, DeepOverlapOnceHitTheIterationLimit) {
  // the Hessian shift of the overlap region was too strong: linear convergence
  const Ellipsoid e1(Vec3(1.365572129656712, 0.75373897354812547, 0.86288824952409748),
                     Vec3(-0.1181516000296365, -0.11792545528717649, 0.0025389240342483573),
                     Quat(-0.7866037415840117, -0.35869477242282405, -0.22296435832034434,
                          -0.4504214791518818));
  const Ellipsoid e2(Vec3(1.9224588283512156, 1.7671528016591402, 1.8999956718101634),
                     Vec3(0.13761807777359275, -0.083459043440685138, 0.15548969510409399),
                     Quat(-0.92380938603706786, 0.19408163112703919, 0.074839047835049716,
                          0.32141508310598438));
  const DistanceResult r = DualNewton().distance(e1, e2, eps(1e-6));
  EXPECT_EQ(r.status, DistanceStatus::overlapping);
  EXPECT_LT(r.iterations, 30);
}

TEST(DualNewtonRegression, NearTangentPairOnceStalledBelowTheRoundingOfL) {
  // gap 1.8e-9: L stopped increasing visibly while |x2 - x1| - L was 4e-9
  const Ellipsoid e1(Vec3(1.6149419896971819, 1.8085716093555859, 0.44091131479186063),
                     Vec3(-1.3553757087649012, 1.5035578435165178, -0.40296722181768779),
                     Quat(0.069566593453791487, -0.96449935137054188, 0.078254487642586357,
                          -0.24244117935044626));
  const Ellipsoid e2(Vec3(1.3818184014488368, 0.29164134868758174, 0.87612566502467004),
                     Vec3(-3.4096283954797664, 0.46238974818607581, -1.1457108966057163),
                     Quat(0.66085356000773665, -0.072256881818373447, 0.73990467418387429,
                          -0.10292030108701283));
  const DistanceResult r = DualNewton().distance(e1, e2, eps(1.8e-12));
  EXPECT_EQ(r.status, DistanceStatus::converged);
  EXPECT_NEAR(r.distance, 1.808571609355586e-09, 5e-12);
  EXPECT_LE(r.bracketWidth(), 1.8e-12);
}

TEST(DualNewtonRegression, MirrorCaseFromEq33OnceStoppedAsOverlapAtAPositiveDistance) {
  // Ar 3/2, d* = 1e-6, eps 1e-4: L was -5.9e-7 with a predicted increase below
  // eps, so the overlap test fired although the next step made L positive
  const MirrorCase m = mirrorCase(1.5, 1e-6, 1);
  DistanceOptions o = eps(1e-4);
  o.useInitialDirection = true;
  o.initialDirection = -Vec3(2 * m.xc, 2 * m.b, 2 * m.b).normalized();
  const DistanceResult r = DualNewton().distance(m.e1, m.e2, o);
  EXPECT_EQ(r.status, DistanceStatus::converged);
  EXPECT_LE(std::abs(r.distance - m.exactDistance), 1e-4);
}

TEST(DualNewtonBatch, SameAnswersAsOneAtATime) {
  // separated, near-touching, overlapping and warm-started pairs, bit for bit
  const DualNewton dual;
  std::mt19937_64 rng(45);
  std::vector<Ellipsoid> bodies;
  std::vector<Vec3> warm;
  for (int k = 0; k < 400; ++k) {
    bodies.push_back(randomEllipsoid(rng, 0.1, 2, 1));
    bodies.push_back(randomEllipsoid(rng, 0.1, 2, 2));
    warm.push_back(randomUnit(rng));
  }
  std::vector<DistancePair> pairs;
  for (int k = 0; k < 400; ++k) {
    pairs.push_back({&bodies[2 * k], &bodies[2 * k + 1], k % 5 == 0 ? &warm[k] : nullptr});
  }
  DistanceOptions o = eps(1e-9);
  std::vector<DistanceResult> batch(pairs.size());
  dual.distances(pairs.data(), pairs.size(), o, batch.data());
  int overlapping = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    DistanceOptions ok = o;
    if (pairs[k].initialDirection) {
      ok.useInitialDirection = true;
      ok.initialDirection = *pairs[k].initialDirection;
    }
    const DistanceResult one = dual.distance(*pairs[k].e1, *pairs[k].e2, ok);
    EXPECT_EQ(batch[k].status, one.status) << k;
    EXPECT_EQ(batch[k].distance, one.distance) << k;
    EXPECT_EQ(batch[k].lower, one.lower) << k;
    EXPECT_EQ(batch[k].upper, one.upper) << k;
    EXPECT_EQ(batch[k].iterations, one.iterations) << k;
    EXPECT_EQ(batch[k].point1, one.point1) << k;
    overlapping += one.status == DistanceStatus::overlapping;
  }
  EXPECT_GT(overlapping, 20);
  // an empty batch reads no pair and writes no result
  DistanceResult untouched;
  untouched.distance = 12345;
  std::vector<DistanceResult> sentinel(3, untouched);
  dual.distances(nullptr, 0, o, sentinel.data());
  dual.distances(pairs.data(), 0, o, sentinel.data());
  for (const DistanceResult& r : sentinel) EXPECT_EQ(r.distance, 12345);
}
