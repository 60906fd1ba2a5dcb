// Random sequential addition: no overlap (periodic images included), count and fraction,
// reproducibility, uniform orientations, the same packing as a plain reference loop,
// invalid options, a body that cannot be placed.
#include "packing/Packing.hpp"
#include "packing/RandomSequentialAddition.hpp"

#include "ellipsoids/OverlapTest.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace {

using ellipsoids::Ellipsoid;
using ellipsoids::JiaOverlapTest;
using ellipsoids::OverlapStatus;
using ellipsoids::Quat;
using ellipsoids::Vec3;
using packing::Packing;
using packing::RsaOptions;

RsaOptions options(double ar, double l, double alpha, std::uint64_t seed = 1) {
  RsaOptions o;
  o.aspectRatio = ar;
  o.boxLengthRelative = l;
  o.volumeFraction = alpha;
  o.seed = seed;
  return o;
}

/// beyond twice the largest semi-axis no contact is possible; check well beyond it
double checkReach(const Packing& p) { return 2 * p.bodies.front().maxSemiAxis() * 1.3; }

struct PairCheck {
  int checked = 0;        ///< pairs close enough to be Jia-tested
  int acrossBoundary = 0;  ///< of which through a periodic image
  int notSeparated = 0;
};

/// every pair whose minimum-image centre distance could allow contact, Jia-tested (O(N^2))
PairCheck checkAllPairs(const Packing& p) {
  PairCheck out;
  const JiaOverlapTest jia;
  const double L = p.boxLength;
  const double reach = checkReach(p);
  for (std::size_t i = 0; i < p.bodies.size(); ++i) {
    for (std::size_t j = i + 1; j < p.bodies.size(); ++j) {
      const Vec3 d = p.bodies[j].centre() - p.bodies[i].centre();
      if (packing::minimumImage(d, L).norm() > reach) continue;
      const packing::NeighbourPair pair{int(i), int(j), packing::periodicShift(d, L)};
      ++out.checked;
      if (!pair.shift.isZero(0)) ++out.acrossBoundary;
      if (jia.test(p.bodies[i], packing::imageOf(p, pair)) != OverlapStatus::separated) {
        ++out.notSeparated;
        ADD_FAILURE() << "bodies " << i << " and " << j << " are "
                      << ellipsoids::toString(jia.test(p.bodies[i], packing::imageOf(p, pair)));
      }
    }
  }
  return out;
}

void expectIdentical(const Packing& a, const Packing& b) {
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  EXPECT_EQ(a.boxLength, b.boxLength);
  EXPECT_EQ(a.volumeFraction, b.volumeFraction);
  for (std::size_t k = 0; k < a.bodies.size(); ++k) {
    ASSERT_EQ(a.bodies[k].centre(), b.bodies[k].centre()) << "body " << k;
    ASSERT_EQ(a.bodies[k].orientation().coeffs(), b.bodies[k].orientation().coeffs()) << "body " << k;
    ASSERT_EQ(a.bodies[k].semiAxes(), b.bodies[k].semiAxes()) << "body " << k;
  }
}

/**
 * The plain algorithm: draw a position and an orientation, Jia-test the candidate against
 * every body placed (its image nearest to that body), keep it or draw again. The library must
 * give exactly this packing: its cells, filters and voxels only save work.
 */
Packing referenceRsa(const RsaOptions& o) {
  const std::size_t n = packing::rsaBodyCount(o);
  const double L = o.boxLengthRelative * o.equivalentDiameter;
  const Vec3 semi =
      Ellipsoid::spheroid(o.aspectRatio, o.equivalentDiameter, Vec3::Zero(), Quat::Identity()).semiAxes();
  const JiaOverlapTest jia;
  std::mt19937_64 engine(o.seed);
  Packing p;
  p.boxLength = L;
  while (p.bodies.size() < n) {
    Vec3 c;
    for (int a = 0; a < 3; ++a) c[a] = L * packing::random::uniform01(engine);
    const Ellipsoid candidate = packing::storableBody(semi, c, packing::random::orientation(engine));
    bool fits = true;
    for (const Ellipsoid& body : p.bodies) {
      const Vec3 shift = packing::periodicShift(c - body.centre(), L);
      if (jia.test(body, Ellipsoid(semi, c + shift, candidate.orientation())) != OverlapStatus::separated) {
        fits = false;
        break;
      }
    }
    if (fits) p.bodies.push_back(candidate);
  }
  p.volumeFraction = packing::volumeFractionOf(n, o.equivalentDiameter, L);
  return p;
}

TEST(RandomSequentialAddition, NoOverlapIncludingPeriodicImages) {
  for (double ar : {6.0, 1.0 / 6, 1.0, 2.5}) {
    SCOPED_TRACE("Ar " + std::to_string(ar));
    const Packing p = packing::randomSequentialAddition(options(ar, 10, 0.25, 3));
    const PairCheck check = checkAllPairs(p);
    EXPECT_EQ(check.notSeparated, 0);
    EXPECT_GT(check.checked, int(p.bodies.size()));  // dense: several close pairs per body
    EXPECT_GT(check.acrossBoundary, 10);
    // the same pairs, found by neighbourPairs
    EXPECT_EQ(int(packing::neighbourPairs(p, checkReach(p)).size()), check.checked);
  }
}

TEST(RandomSequentialAddition, CountFractionAndBodies) {
  RsaOptions o = options(2, 12, 0.2, 5);
  o.equivalentDiameter = 2e-3;  // SI metres: everything scales
  packing::RsaStatistics stats;
  const Packing p = packing::randomSequentialAddition(o, &stats);
  const double D = 2e-3, L = 12 * D;
  const std::size_t n = static_cast<std::size_t>(std::round(0.2 * 12 * 12 * 12 * 6 / packing::kPi));
  EXPECT_EQ(n, 660u);
  ASSERT_EQ(p.bodies.size(), n);
  EXPECT_EQ(stats.bodies, n);
  EXPECT_GE(stats.attempts, n);
  EXPECT_GE(stats.maxAttemptsForOneBody, 1);
  EXPECT_DOUBLE_EQ(p.boxLength, L);
  EXPECT_EQ(p.aspectRatio, 2);
  EXPECT_EQ(p.equivalentDiameter, D);
  EXPECT_EQ(p.seed, 5u);
  EXPECT_NEAR(p.volumeFraction, n * packing::kPi / 6 * D * D * D / (L * L * L), 1e-15);
  EXPECT_NEAR(p.volumeFraction, 0.2, 0.5 / (12 * 12 * 12 * 6 / packing::kPi));  // N rounded
  const double a = std::cbrt(4.0) * D / 2, b = D / 2 / std::cbrt(2.0);
  Vec3 mean = Vec3::Zero();
  for (const Ellipsoid& e : p.bodies) {
    EXPECT_NEAR(e.semiAxes().x(), a, 1e-15);
    EXPECT_NEAR(e.semiAxes().y(), b, 1e-15);
    EXPECT_EQ(e.semiAxes().y(), e.semiAxes().z());
    EXPECT_NEAR(e.equivalentRadius(), D / 2, 1e-15);
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(e.centre()[k], 0);
      EXPECT_LT(e.centre()[k], L);
    }
    EXPECT_NEAR(e.orientation().norm(), 1, 1e-15);
    mean += e.centre() / double(n);
  }
  // positions uniform in the box: mean centre near the middle (sd L / sqrt(12 n) = 0.011 L)
  EXPECT_NEAR(mean.x(), L / 2, 0.06 * L);
  EXPECT_NEAR(mean.y(), L / 2, 0.06 * L);
  EXPECT_NEAR(mean.z(), L / 2, 0.06 * L);
  EXPECT_EQ(checkAllPairs(p).notSeparated, 0);
}

TEST(RandomSequentialAddition, ReproducibleFromTheSeed) {
  const Packing a = packing::randomSequentialAddition(options(6, 9, 0.2, 42));
  const Packing b = packing::randomSequentialAddition(options(6, 9, 0.2, 42));
  expectIdentical(a, b);
  const Packing c = packing::randomSequentialAddition(options(6, 9, 0.2, 43));
  ASSERT_EQ(c.bodies.size(), a.bodies.size());
  int same = 0;
  for (std::size_t k = 0; k < a.bodies.size(); ++k) same += a.bodies[k].centre() == c.bodies[k].centre();
  EXPECT_EQ(same, 0);
  EXPECT_EQ(c.seed, 43u);
}

TEST(RandomSequentialAddition, SameDrawsOnEveryMachine) {
  // the engine's output is fixed by the C++ standard (its 10000th number, [rand.predef])
  std::mt19937_64 standard;
  standard.discard(9999);
  EXPECT_EQ(standard(), 9981545732273789042ull);
  // the first body is the first candidate: position L (x >> 11) 2^-53 from the first three
  // numbers of mt19937_64(1), then the orientation
  const Packing p = packing::randomSequentialAddition(options(6, 10, 0.05, 1));
  EXPECT_EQ(p.bodies[0].centre(), Vec3(0x1.56b965bd52141p+0, 0x1.5d33b7215ef9bp+0, 0x1.20c70cc2b33fap+2));
  const Quat q = p.bodies[0].orientation();
  EXPECT_NEAR(q.w(), 0x1.a53b0b4ae64dbp-1, 1e-15);
  EXPECT_NEAR(q.x(), -0x1.df32729ba90c1p-5, 1e-15);
  EXPECT_NEAR(q.y(), -0x1.1dae363ea46e6p-1, 1e-15);
  EXPECT_NEAR(q.z(), 0x1.7718c026fcc9ap-4, 1e-15);
  std::mt19937_64 engine(1);
  Vec3 c;
  for (int a = 0; a < 3; ++a) c[a] = 10 * (double(engine() >> 11) * 0x1.0p-53);
  EXPECT_EQ(p.bodies[0].centre(), c);
  const Quat q0 = packing::random::orientation(engine);
  EXPECT_EQ(p.bodies[0].orientation().coeffs(),
            packing::storableBody(p.bodies[0].semiAxes(), c, q0).orientation().coeffs());
}

TEST(RandomSequentialAddition, SamePackingAsThePlainReferenceLoop) {
  // a box under 3 cutoffs a side (every body scanned) and one with a cell list
  for (const RsaOptions& o : {options(6, 8, 0.2, 9), options(1.0 / 6, 8, 0.2, 9), options(2, 8, 0.2, 9)}) {
    SCOPED_TRACE("Ar " + std::to_string(o.aspectRatio));
    packing::RsaStatistics stats;
    const Packing fast = packing::randomSequentialAddition(o, &stats);
    const Packing plain = referenceRsa(o);
    expectIdentical(fast, plain);
    EXPECT_GT(stats.voxelRejections, 0u);  // the shortcuts were used
    EXPECT_GT(stats.jiaTests, 0u);
  }
}

TEST(RandomSequentialAddition, UniformOrientations) {
  // body x axes of a dilute packing: components mean 0 (sd 1/sqrt(3N)), squares 1/3
  // (sd sqrt(4/45/N)); tolerances 5 sd
  const Packing p = packing::randomSequentialAddition(options(6, 40, 0.03, 17));
  const double n = double(p.bodies.size());
  ASSERT_GT(n, 3000);
  Vec3 mean = Vec3::Zero(), mean2 = Vec3::Zero();
  for (const Ellipsoid& e : p.bodies) {
    const Vec3 axis = e.rotation().col(0);
    mean += axis / n;
    mean2 += axis.cwiseProduct(axis) / n;
  }
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(mean[k], 0, 5 / std::sqrt(3 * n)) << "component " << k;
    EXPECT_NEAR(mean2[k], 1.0 / 3, 5 * std::sqrt(4.0 / 45 / n)) << "component " << k;
  }
}

TEST(RandomSequentialAddition, OrientationSamplerIsUniformOnSO3) {
  // the whole rotation matrix: E[R_ij] = 0, E[R_ij^2] = 1/3 (sd 1/sqrt(3N), sqrt(4/45/N))
  std::mt19937_64 engine(2024);
  const int n = 200000;
  ellipsoids::Mat3 mean = ellipsoids::Mat3::Zero(), mean2 = ellipsoids::Mat3::Zero();
  double wNegative = 0;
  for (int k = 0; k < n; ++k) {
    const Quat q = packing::random::orientation(engine);
    ASSERT_NEAR(q.norm(), 1, 5e-16);
    if (k < 100000) {  // what the bodies keep: an Ellipsoid rebuilt from it is the same
      const Ellipsoid e = packing::storableBody(Vec3(1, 2, 3), Vec3::Zero(), q);
      ASSERT_LE((e.orientation().coeffs() - q.coeffs()).cwiseAbs().maxCoeff(), 1e-15);
      ASSERT_EQ(Ellipsoid(Vec3(1, 2, 3), Vec3(4, 5, 6), e.orientation()).orientation().coeffs(),
                e.orientation().coeffs());
    }
    const ellipsoids::Mat3 R = q.toRotationMatrix();
    mean += R / n;
    mean2 += R.cwiseProduct(R) / n;
    wNegative += q.w() < 0;
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(mean(i, j), 0, 5 / std::sqrt(3.0 * n)) << i << j;
      EXPECT_NEAR(mean2(i, j), 1.0 / 3, 5 * std::sqrt(4.0 / 45 / n)) << i << j;
    }
  }
  EXPECT_NEAR(wNegative / n, 0.5, 5 * 0.5 / std::sqrt(double(n)));
  // uniform01: in [0, 1), multiples of 2^-53
  std::mt19937_64 e2(3);
  for (int k = 0; k < 1000; ++k) {
    const double u = packing::random::uniform01(e2);
    ASSERT_GE(u, 0);
    ASSERT_LT(u, 1);
    ASSERT_EQ(u * 0x1.0p53, std::floor(u * 0x1.0p53));
  }
}

void expectInvalid(const RsaOptions& o, const std::string& option, const std::string& inMessage) {
  try {
    packing::randomSequentialAddition(o);
    ADD_FAILURE() << "no exception for an invalid " << option;
  } catch (const packing::InvalidRsaOption& e) {
    EXPECT_EQ(e.option(), option);
    const std::string what = e.what();
    EXPECT_NE(what.find(option), std::string::npos) << what;
    EXPECT_NE(what.find(inMessage), std::string::npos) << what;
  }
  EXPECT_THROW(packing::validate(o), std::invalid_argument);
}

TEST(RandomSequentialAddition, InvalidOptionsThrow) {
  const double nan = std::nan(""), inf = HUGE_VAL;
  expectInvalid(options(0, 10, 0.1), "aspectRatio", "> 0");
  expectInvalid(options(-2, 10, 0.1), "aspectRatio", "> 0");
  expectInvalid(options(nan, 10, 0.1), "aspectRatio", "> 0");
  expectInvalid(options(inf, 10, 0.1), "aspectRatio", "> 0");
  expectInvalid(options(1, 10, 0), "volumeFraction", "(0, 0.3]");
  expectInvalid(options(1, 10, 0.31), "volumeFraction", "(0, 0.3]");
  expectInvalid(options(1, 10, nan), "volumeFraction", "(0, 0.3]");
  expectInvalid(options(1, 10, 1e-7), "volumeFraction", "0 bodies");
  // twice the longest body: 2 * 6^(2/3) = 6.604 for Ar 6, 2 * 6^(1/3) = 3.634 for Ar 1/6, 2 for spheres
  expectInvalid(options(6, 6.6, 0.1), "boxLengthRelative", "6.60");
  expectInvalid(options(1.0 / 6, 3.6, 0.1), "boxLengthRelative", "3.63");
  expectInvalid(options(1, 2, 0.1), "boxLengthRelative", "> 2");
  expectInvalid(options(1, nan, 0.1), "boxLengthRelative", "finite");
  expectInvalid(options(1, 1e4, 0.3), "boxLengthRelative", "1e8 bodies");
  RsaOptions o = options(1, 10, 0.1);
  o.equivalentDiameter = 0;
  expectInvalid(o, "equivalentDiameter", "> 0");
  o = options(1, 10, 0.1);
  o.maxAttemptsPerBody = 0;
  expectInvalid(o, "maxAttemptsPerBody", ">= 1");
  o = options(1, 10, 0.1);
  o.wallClearance = -0.1;
  expectInvalid(o, "wallClearance", ">= 0");
  o.walls = true;
  o.wallClearance = 4.6;  // spheres: l/2 - a_max/D = 4.5
  expectInvalid(o, "wallClearance", "< l/2 - a_max/D_eq = 4.5");
  EXPECT_NO_THROW(packing::validate(options(6, 6.61, 0.1)));
  EXPECT_NEAR(packing::minimumBoxLengthRelative(6), 2 * std::cbrt(36.0), 1e-5);
}

TEST(RandomSequentialAddition, WithWallsEveryBodyIsInsideTheBoxAndClearOfItsFaces) {
  for (double ar : {2.0, 1.0 / 6, 6.0}) {
    SCOPED_TRACE("Ar " + std::to_string(ar));
    RsaOptions o = options(ar, 8, 0.2, 7);
    o.walls = true;
    o.wallClearance = 0.05;
    o.equivalentDiameter = 4e-3;
    packing::RsaStatistics stats;
    const Packing p = packing::randomSequentialAddition(o, &stats);
    ASSERT_EQ(p.bodies.size(), packing::rsaBodyCount(o));
    EXPECT_GT(stats.wallRejections, 0u);
    const double L = p.boxLength, gap = 0.05 * 4e-3;
    double closest = L;
    for (const Ellipsoid& b : p.bodies) {
      for (int a = 0; a < 3; ++a) {
        // the support along the axis from the body's own semi-axes and orientation
        const Vec3 e = Vec3::Unit(a);
        const Vec3 local = b.orientation().conjugate() * e;
        const double h = std::sqrt((local.cwiseProduct(b.semiAxes())).squaredNorm());
        closest = std::min({closest, b.centre()[a] - h, L - b.centre()[a] - h});
      }
    }
    EXPECT_GE(closest, gap * (1 - 1e-9));
    EXPECT_LT(closest, 0.3 * gap + gap);  // the walls are reached, not avoided by a margin
    EXPECT_EQ(checkAllPairs(p).notSeparated, 0);
  }
}

TEST(RandomSequentialAddition, ABodyThatCannotBePlacedEndsWithAClearError) {
  RsaOptions o = options(1, 5, 0.3, 1);
  o.maxAttemptsPerBody = 3;
  packing::RsaStatistics stats;
  try {
    packing::randomSequentialAddition(o, &stats);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("body "), std::string::npos) << what;
    EXPECT_NE(what.find("after 3 attempts"), std::string::npos) << what;
    EXPECT_NE(what.find("volume fraction reached"), std::string::npos) << what;
  }
  EXPECT_LE(stats.maxAttemptsForOneBody, 3);
  EXPECT_GE(stats.attempts, 3u);
}

}  // namespace
