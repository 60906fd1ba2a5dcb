#include "collision/PairSearch.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include <random>

using namespace collision;

namespace {
std::vector<std::pair<int, int>> bruteForce(const std::vector<Vec3>& c, const std::vector<Scalar>& r) {
  std::vector<std::pair<int, int>> out;
  for (int i = 0; i < int(c.size()); ++i)
    for (int j = i + 1; j < int(c.size()); ++j)
      if ((c[i] - c[j]).norm() <= r[i] + r[j]) out.emplace_back(i, j);
  return out;
}
}  // namespace

TEST(PairSearch, SameAsAllPairsForRandomBodiesOfSeveralSizes) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<Scalar> pos(-5, 5), rad(0.05, 0.6);
  PairSearch search;
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<Vec3> c;
    std::vector<Scalar> r;
    for (int i = 0; i < 400; ++i) {
      c.emplace_back(pos(gen), pos(gen), trial == 4 ? 0.0 : pos(gen));  // trial 4: a plane layer
      r.push_back(rad(gen));
    }
    auto found = search.find(c, r);
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, bruteForce(c, r)) << "trial " << trial;
    EXPECT_FALSE(found.empty());
  }
}

TEST(PairSearch, HugeSpanAndTinyBodiesStillExact) {
  std::vector<Vec3> c{Vec3(0, 0, 0), Vec3(1e-6, 0, 0), Vec3(1e6, 0, 0), Vec3(1e6, 1.5e-6, 0)};
  std::vector<Scalar> r{1e-6, 1e-6, 1e-6, 1e-6};
  PairSearch search;
  auto found = search.find(c, r);
  std::sort(found.begin(), found.end());
  EXPECT_EQ(found, bruteForce(c, r));
  EXPECT_EQ(search.find(c, r).size(), 2u);
}

TEST(PairSearch, BadInputThrowsWithTheBody) {
  PairSearch search;
  std::vector<Vec3> c{Vec3::Zero(), Vec3(std::nan(""), 0, 0)};
  std::vector<Scalar> r{1, 1};
  EXPECT_THROW(search.find(c, r), std::invalid_argument);
  c[1] = Vec3::Ones();
  r[0] = 0;
  EXPECT_THROW(search.find(c, r), std::invalid_argument);
}
