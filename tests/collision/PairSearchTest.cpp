// PairSearch: the candidate pairs are exactly the pairs whose bounding
// spheres meet, through the minimum image along periodic axes.
#include "collision/PairSearch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace collision;

namespace {

bool byPairThenImage(const CandidatePair& a, const CandidatePair& b) {
  return a.first != b.first ? a.first < b.first
                            : (a.second != b.second ? a.second < b.second : a.image < b.image);
}

/// Every pair and every image of the second within kMaxMultiple periods, tested one by one.
std::vector<CandidatePair> bruteForce(const std::vector<Vec3>& c, const std::vector<Scalar>& r,
                                      const PeriodicBox& box = PeriodicBox()) {
  std::vector<CandidatePair> out;
  const int m = PeriodicBox::kMaxMultiple;
  for (int i = 0; i < int(c.size()); ++i)
    for (int j = i + 1; j < int(c.size()); ++j)
      for (int kx = -m; kx <= m; ++kx)
        for (int ky = -m; ky <= m; ++ky)
          for (int kz = -m; kz <= m; ++kz) {
            const std::array<int, 3> k{kx, ky, kz};
            bool needed = true;  // only the multiples of periodic axes
            for (int d = 0; d < 3; ++d) needed = needed && (box.periodic(d) || k[d] == 0);
            if (!needed) continue;
            if ((c[j] + box.shift(k) - c[i]).norm() <= r[i] + r[j]) {
              out.push_back({i, j, PeriodicBox::imageCode(k)});
            }
          }
  std::sort(out.begin(), out.end(), byPairThenImage);
  return out;
}

std::vector<CandidatePair> sorted(std::vector<CandidatePair> v) {
  std::sort(v.begin(), v.end(), byPairThenImage);
  return v;
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
    const auto found = sorted(search.find(c, r));
    EXPECT_EQ(found, bruteForce(c, r)) << "trial " << trial;
    EXPECT_FALSE(found.empty());
    for (const CandidatePair& p : found) EXPECT_EQ(p.image, PeriodicBox::kNoImage);
  }
}

TEST(PairSearch, HugeSpanAndTinyBodiesStillExact) {
  std::vector<Vec3> c{Vec3(0, 0, 0), Vec3(1e-6, 0, 0), Vec3(1e6, 0, 0), Vec3(1e6, 1.5e-6, 0)};
  std::vector<Scalar> r{1e-6, 1e-6, 1e-6, 1e-6};
  PairSearch search;
  EXPECT_EQ(sorted(search.find(c, r)), bruteForce(c, r));
  EXPECT_EQ(search.find(c, r).size(), 2u);
}

TEST(PairSearch, PeriodicAxesGiveTheMinimumImageOfEveryPair) {
  // one, two and three periodic axes; boxes of 2 and more cells per axis
  // (2: the neighbour across the wrap is the same cell on both sides); centres
  // up to a period outside the box (bodies between two wraps)
  std::mt19937 gen(11);
  std::uniform_real_distribution<Scalar> unit(0, 1), rad(0.2, 0.5);
  const std::array<bool, 3> axes[] = {{true, false, false}, {false, true, true}, {true, true, true}};
  for (const auto& periodic : axes) {
    for (const Scalar side : {2.1, 3.0, 7.0}) {  // 2 rMax = 1: 2, 3 and 7 cells per periodic axis
      const PeriodicBox box(Vec3(-1, 2, 0.5), Vec3(side, side * 1.1, side * 1.05), periodic);
      std::vector<Vec3> c;
      std::vector<Scalar> r;
      for (int i = 0; i < 150; ++i) {
        Vec3 x;
        for (int d = 0; d < 3; ++d) {
          x[d] = box.origin()[d] + box.length()[d] * (unit(gen) * 1.6 - 0.3);  // up to 0.3 L outside
        }
        c.push_back(x);
        r.push_back(rad(gen));
      }
      r[0] = 0.5;  // rMax = 0.5
      PairSearch search;
      const auto found = sorted(search.find(c, r, box));
      const auto expected = bruteForce(c, r, box);
      EXPECT_EQ(found, expected) << "periodic " << periodic[0] << periodic[1] << periodic[2]
                                 << ", side " << side;
      // each pair meets through one image only (the periods exceed twice the range)
      for (std::size_t k = 1; k < expected.size(); ++k) {
        EXPECT_FALSE(expected[k].first == expected[k - 1].first && expected[k].second == expected[k - 1].second);
      }
      // and the search finds pairs across the periodic faces
      EXPECT_TRUE(std::any_of(found.begin(), found.end(),
                              [](const CandidatePair& p) { return p.image != PeriodicBox::kNoImage; }));
    }
  }
}

TEST(PairSearch, FlaggedFirstBodiesGiveTheirShareOfThePairs) {
  // the bodies split among 3 "processes" by a flag each: every pair found by
  // exactly the process that flags its first body, the union the full search;
  // without and with periodic axes (3 cells per axis: a neighbour across the
  // wrap; 2: the same cell on both sides)
  std::mt19937 gen(5);
  std::uniform_real_distribution<Scalar> unit(0, 1), rad(0.1, 0.5);
  for (const Scalar side : {0.0, 2.1, 3.0}) {
    const PeriodicBox box = side > 0 ? PeriodicBox(Vec3::Zero(), Vec3::Constant(side), {true, true, true})
                                     : PeriodicBox();
    std::vector<Vec3> c;
    std::vector<Scalar> r;
    for (int i = 0; i < 300; ++i) {
      c.push_back((side > 0 ? side : 6.0) * Vec3(unit(gen), unit(gen), unit(gen)));
      r.push_back(rad(gen));
    }
    r[0] = 0.5;
    PairSearch search;
    const auto all = sorted(search.find(c, r, box));
    ASSERT_FALSE(all.empty());
    std::vector<CandidatePair> united;
    for (int rank = 0; rank < 3; ++rank) {
      std::vector<char> mine(c.size());
      for (std::size_t i = 0; i < c.size(); ++i) mine[i] = (i * 7 + 3) % 3 == std::size_t(rank);
      const auto share = sorted(search.find(c, r, box, &mine));
      for (const CandidatePair& p : share) EXPECT_TRUE(mine[p.first]) << "side " << side;
      EXPECT_TRUE(std::adjacent_find(share.begin(), share.end()) == share.end()) << "side " << side;
      united.insert(united.end(), share.begin(), share.end());
    }
    EXPECT_EQ(sorted(united), all) << "side " << side;
  }
  std::vector<char> tooFew(2);
  PairSearch search;
  EXPECT_THROW(search.find({Vec3::Zero(), Vec3::Ones(), Vec3::Zero()}, {1, 1, 1}, PeriodicBox(), &tooFew),
               std::invalid_argument);
}

TEST(PairSearch, APeriodTooShortForTheBodiesIsRejected) {
  // radius 0.5 each: a pair reaches 1, so a period must exceed 2
  const PeriodicBox box(Vec3::Zero(), Vec3(1.9, 10, 10), {true, false, false});
  PairSearch search;
  std::vector<Vec3> c{Vec3(0.1, 1, 1), Vec3(1.0, 1, 1)};
  std::vector<Scalar> r{0.5, 0.5};
  try {
    search.find(c, r, box);
    FAIL() << "a period of 1.9 accepted for a pair range of 1";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("along x"), std::string::npos) << e.what();
  }
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
