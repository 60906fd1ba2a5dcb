#include "collision/PairSearch.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace collision {

namespace {
// 21 bits per cell coordinate
constexpr std::int64_t kBits = 21;
constexpr std::int64_t kMask = (std::int64_t(1) << kBits) - 1;

std::int64_t cellKey(std::int64_t i, std::int64_t j, std::int64_t k) {
  return (i << (2 * kBits)) | (j << kBits) | k;
}
}  // namespace

const std::vector<std::pair<int, int>>& PairSearch::find(const std::vector<Vec3>& centres,
                                                         const std::vector<Scalar>& radii) {
  pairs_.clear();
  const int n = static_cast<int>(centres.size());
  if (radii.size() != centres.size()) {
    throw std::invalid_argument("PairSearch: " + std::to_string(centres.size()) + " centres but " +
                                std::to_string(radii.size()) + " radii");
  }
  if (n < 2) return pairs_;
  Vec3 lo = centres[0], hi = centres[0];
  Scalar rMax = 0;
  for (int i = 0; i < n; ++i) {
    if (!centres[i].allFinite() || !(radii[i] > 0) || !std::isfinite(radii[i])) {
      throw std::invalid_argument("PairSearch: body " + std::to_string(i) +
                                  " has a non-finite centre or a radius that is not > 0");
    }
    lo = lo.cwiseMin(centres[i]);
    hi = hi.cwiseMax(centres[i]);
    rMax = std::max(rMax, radii[i]);
  }
  // cells of size 2 rMax, at most 2^21 per direction (larger spans: bigger cells)
  Scalar cell = 2 * rMax;
  const Scalar span = (hi - lo).maxCoeff();
  cell = std::max(cell, span / Scalar(kMask - 2));
  entries_.resize(n);
  for (int i = 0; i < n; ++i) {
    const Vec3 c = (centres[i] - lo) / cell;
    entries_[i] = {cellKey(std::int64_t(c.x()) + 1, std::int64_t(c.y()) + 1,
                           std::int64_t(c.z()) + 1),
                   i};
  }
  std::sort(entries_.begin(), entries_.end(),
            [](const Entry& a, const Entry& b) { return a.key < b.key || (a.key == b.key && a.body < b.body); });
  auto rangeOf = [this](std::int64_t key) {
    auto first = std::lower_bound(entries_.begin(), entries_.end(), key,
                                  [](const Entry& e, std::int64_t k) { return e.key < k; });
    auto last = first;
    while (last != entries_.end() && last->key == key) ++last;
    return std::make_pair(first, last);
  };
  for (auto it = entries_.begin(); it != entries_.end();) {
    const std::int64_t key = it->key;
    auto cellEnd = it;
    while (cellEnd != entries_.end() && cellEnd->key == key) ++cellEnd;
    const std::int64_t ci = key >> (2 * kBits), cj = (key >> kBits) & kMask, ck = key & kMask;
    // the 13 "forward" neighbours and the cell itself: each pair once
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj)
        for (int dk = -1; dk <= 1; ++dk) {
          const std::int64_t nkey = cellKey(ci + di, cj + dj, ck + dk);
          if (nkey < key) continue;
          auto [first, last] = nkey == key ? std::make_pair(it, cellEnd) : rangeOf(nkey);
          for (auto a = it; a != cellEnd; ++a) {
            for (auto b = first; b != last; ++b) {
              if (nkey == key && b->body <= a->body) continue;
              const int i = std::min(a->body, b->body), j = std::max(a->body, b->body);
              const Scalar reach = radii[i] + radii[j];
              if ((centres[i] - centres[j]).squaredNorm() <= reach * reach) {
                pairs_.emplace_back(i, j);
              }
            }
          }
        }
    it = cellEnd;
  }
  std::sort(pairs_.begin(), pairs_.end());
  return pairs_;
}

}  // namespace collision

