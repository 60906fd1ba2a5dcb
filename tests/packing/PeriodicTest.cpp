// minimumImage, periodicShift, neighbourPairs (against a brute-force search) and imageOf.
#include "packing/Packing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <tuple>
#include <vector>

namespace {

using ellipsoids::Ellipsoid;
using ellipsoids::Vec3;
using packing::NeighbourPair;
using packing::Packing;

Packing pointsPacking(double L, const std::vector<Vec3>& centres) {
  Packing p;
  p.boxLength = L;
  for (const Vec3& c : centres) p.bodies.push_back(Ellipsoid::sphere(0.01, c));
  return p;
}

/// every pair i < j with minimumImage(c_j - c_i).squaredNorm() <= cutoff^2 (O(N^2))
std::vector<NeighbourPair> bruteForce(const Packing& p, double cutoff) {
  std::vector<NeighbourPair> out;
  const int n = static_cast<int>(p.bodies.size());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const Vec3 d = p.bodies[std::size_t(j)].centre() - p.bodies[std::size_t(i)].centre();
      if (packing::minimumImage(d, p.boxLength).squaredNorm() <= cutoff * cutoff) {
        out.push_back(NeighbourPair{i, j, packing::periodicShift(d, p.boxLength)});
      }
    }
  }
  return out;
}

void expectSamePairs(const std::vector<NeighbourPair>& got, const std::vector<NeighbourPair>& want,
                     const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t k = 0; k < got.size(); ++k) {
    EXPECT_EQ(got[k].i, want[k].i) << what << ", pair " << k;
    EXPECT_EQ(got[k].j, want[k].j) << what << ", pair " << k;
    EXPECT_EQ(got[k].shift, want[k].shift) << what << ", pair " << k;
  }
}

/// random points in [0, L)^3 plus points on the faces, near the far faces and across them
std::vector<Vec3> testPoints(double L, int n, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  std::vector<Vec3> c;
  for (int k = 0; k < n; ++k) {
    c.emplace_back(L * (double(engine() >> 11) * 0x1.0p-53), L * (double(engine() >> 11) * 0x1.0p-53),
                   L * (double(engine() >> 11) * 0x1.0p-53));
  }
  const double top = std::nextafter(L, 0.0);
  c.emplace_back(0, 0, 0);
  c.emplace_back(top, top, top);  // a corner image away from the origin
  c.emplace_back(0.05 * L, 0.5 * L, 0.5 * L);
  c.emplace_back(0.95 * L, 0.5 * L, 0.5 * L);  // 0.1 L across the x faces
  c.emplace_back(0.5 * L, 0.02 * L, 0.98 * L);
  c.emplace_back(0.5 * L, 0.99 * L, 0.01 * L);  // across y and z at once
  return c;
}

TEST(MinimumImage, ComponentsWithinHalfABox) {
  const double L = 3;
  EXPECT_EQ(packing::minimumImage(Vec3(0.6 * L, -0.6 * L, 0.2 * L), L),
            Vec3(0.6 * L - L, -0.6 * L + L, 0.2 * L));
  EXPECT_NEAR((packing::minimumImage(Vec3(2.3 * L, -4.7 * L, 0), L) - Vec3(0.3 * L, 0.3 * L, 0)).norm(),
              0, 1e-14);
  // exactly half a box: std::round goes away from zero, so +L/2 -> -L/2 and -L/2 -> +L/2
  EXPECT_EQ(packing::minimumImage(Vec3(L / 2, -L / 2, 0), L), Vec3(-L / 2, L / 2, 0));
  std::mt19937_64 engine(7);
  for (int k = 0; k < 10000; ++k) {
    Vec3 d;
    for (int a = 0; a < 3; ++a) d[a] = (double(engine() >> 11) * 0x1.0p-53 - 0.5) * 10 * L;
    const Vec3 m = packing::minimumImage(d, L);
    const Vec3 s = packing::periodicShift(d, L);
    EXPECT_EQ(m, d + s);
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(std::abs(m[a]), L / 2 * (1 + 1e-14));
      EXPECT_EQ(s[a] / L, std::round(s[a] / L));  // an integer number of boxes
    }
  }
}

TEST(NeighbourPairs, MatchBruteForceForManyCutoffs) {
  const double L = 10;
  const Packing p = pointsPacking(L, testPoints(L, 400, 11));
  // 20 cells a side, 10, 4, 3 (1/3 box), 2, 1, and a cutoff beyond half the box
  for (double cutoff : {0.5, 1.0, 2.4, 3.3, 4.0, 6.0, 9.0}) {
    expectSamePairs(packing::neighbourPairs(p, cutoff), bruteForce(p, cutoff),
                    "cutoff " + std::to_string(cutoff));
  }
}

TEST(NeighbourPairs, SmallBoxOfThreeCells) {
  const double L = 3;
  const Packing p = pointsPacking(L, testPoints(L, 150, 12));
  for (double cutoff : {1.0, 0.999, 1.2, 1.5}) {
    expectSamePairs(packing::neighbourPairs(p, cutoff), bruteForce(p, cutoff),
                    "L 3, cutoff " + std::to_string(cutoff));
  }
}

TEST(NeighbourPairs, BoundaryCrossingPairsAndTheirShifts) {
  const double L = 5;
  // across x, across y and z, across the corner; one pair inside; one pair just too far
  const std::vector<Vec3> c = {Vec3(0.1, 2, 2),     Vec3(4.85, 2, 2),    Vec3(1, 0.05, 4.9),
                               Vec3(1, 4.9, 0.05),  Vec3(0, 0, 0),       Vec3(4.9, 4.9, 4.9),
                               Vec3(2.5, 2.5, 2.5), Vec3(2.5, 2.5, 2.75), Vec3(2.5, 1.0, 1.0),
                               Vec3(2.5, 1.0, 1.5)};
  const Packing p = pointsPacking(L, c);
  const double cutoff = 0.3;
  const auto pairs = packing::neighbourPairs(p, cutoff);
  expectSamePairs(pairs, bruteForce(p, cutoff), "hand-made");
  std::set<std::tuple<int, int>> found;
  for (const auto& q : pairs) found.insert({q.i, q.j});
  EXPECT_EQ(found, (std::set<std::tuple<int, int>>{{0, 1}, {2, 3}, {4, 5}, {6, 7}}));
  for (const auto& q : pairs) {
    const Ellipsoid image = packing::imageOf(p, q);
    const Vec3 ci = p.bodies[std::size_t(q.i)].centre();
    EXPECT_LE((image.centre() - ci).norm(), cutoff * (1 + 1e-15));
    EXPECT_EQ(image.semiAxes(), p.bodies[std::size_t(q.j)].semiAxes());
    EXPECT_EQ(image.orientation().coeffs(), p.bodies[std::size_t(q.j)].orientation().coeffs());
  }
  EXPECT_EQ(pairs[0].shift, Vec3(-L, 0, 0));        // 4.85 -> -0.15, next to 0.1
  EXPECT_EQ(pairs[2].shift, Vec3(-L, -L, -L));      // (4.9,4.9,4.9) -> (-0.1,-0.1,-0.1)
}

TEST(NeighbourPairs, DistanceEqualToTheCutoffCounts) {
  const double L = 8;
  // exact binary fractions: (0,1) exactly 0.75 apart, (0,2) exactly 0.75 across the x faces,
  // (1,2) 1.5 apart
  const Packing p = pointsPacking(L, {Vec3(0.5, 1, 1), Vec3(1.25, 1, 1), Vec3(7.75, 1, 1)});
  const auto pairs = packing::neighbourPairs(p, 0.75);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].j, 1);
  EXPECT_EQ(pairs[1].j, 2);
  EXPECT_EQ(pairs[1].shift, Vec3(-L, 0, 0));
  EXPECT_TRUE(packing::neighbourPairs(p, std::nextafter(0.75, 0.0)).empty());
}

TEST(NeighbourPairs, CentresOutsideTheBoxAreBinnedAfterWrapping) {
  const double L = 6;
  std::vector<Vec3> c = testPoints(L, 200, 13);
  c.emplace_back(-0.1, 3, 3);
  c.emplace_back(6.05, 3, 3);
  c.emplace_back(-6.2, 3.1, 2.9);
  const Packing p = pointsPacking(L, c);
  for (double cutoff : {0.7, 1.9}) {
    expectSamePairs(packing::neighbourPairs(p, cutoff), bruteForce(p, cutoff),
                    "wrapped, cutoff " + std::to_string(cutoff));
  }
}

TEST(NeighbourPairs, SortedAndEachPairOnce) {
  const Packing p = pointsPacking(12, testPoints(12, 500, 14));
  const auto pairs = packing::neighbourPairs(p, 1.7);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    EXPECT_LT(pairs[k].i, pairs[k].j);
    if (k > 0) {
      EXPECT_TRUE(std::tie(pairs[k - 1].i, pairs[k - 1].j) < std::tie(pairs[k].i, pairs[k].j));
    }
  }
}

TEST(NeighbourPairs, EdgeCasesAndInvalidInput) {
  EXPECT_TRUE(packing::neighbourPairs(pointsPacking(5, {}), 1).empty());
  EXPECT_TRUE(packing::neighbourPairs(pointsPacking(5, {Vec3(1, 1, 1)}), 1).empty());
  const Packing two = pointsPacking(5, {Vec3(1, 1, 1), Vec3(1, 1, 1)});
  EXPECT_EQ(packing::neighbourPairs(two, 0).size(), 1u);  // coincident centres, zero cutoff
  EXPECT_THROW(packing::neighbourPairs(two, -1), std::invalid_argument);
  EXPECT_THROW(packing::neighbourPairs(two, std::nan("")), std::invalid_argument);
  EXPECT_THROW(packing::neighbourPairs(pointsPacking(0, {Vec3(1, 1, 1)}), 1), std::invalid_argument);
  EXPECT_THROW(packing::imageOf(two, NeighbourPair{0, 5, Vec3::Zero()}), std::out_of_range);
}

}  // namespace
