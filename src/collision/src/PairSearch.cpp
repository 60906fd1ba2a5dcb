#include "collision/PairSearch.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace collision {

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

  // a dense grid of cells of size >= 2 rMax (a pair can only meet in
  // neighbouring cells), with at most about 2 n + 27 cells in all so that
  // sparse or widely spread sets stay O(n) in memory and time
  const Vec3 span = hi - lo;
  Scalar cell = 2 * rMax;
  const Scalar maxCells = 2.0 * n + 27;
  for (int pass = 0; pass < 64; ++pass) {
    const Scalar cells = (std::floor(span.x() / cell) + 1) * (std::floor(span.y() / cell) + 1) *
                         (std::floor(span.z() / cell) + 1);
    if (cells <= maxCells) break;
    cell *= std::cbrt(cells / maxCells) * 1.01;
  }
  if (!((std::floor(span.x() / cell) + 1) * (std::floor(span.y() / cell) + 1) *
            (std::floor(span.z() / cell) + 1) <= maxCells)) {
    throw std::runtime_error("PairSearch: no cell size found for " + std::to_string(n) +
                             " bodies spanning " + std::to_string(span.maxCoeff()));
  }
  for (int d = 0; d < 3; ++d) dims_[d] = static_cast<int>(std::floor(span[d] / cell)) + 1;
  const int nCells = dims_[0] * dims_[1] * dims_[2];

  // counting sort of the bodies by cell
  cellOf_.resize(n);
  cellStart_.assign(nCells + 1, 0);
  for (int i = 0; i < n; ++i) {
    const Vec3 c = (centres[i] - lo) / cell;
    int idx[3];
    for (int d = 0; d < 3; ++d) idx[d] = std::min(static_cast<int>(c[d]), dims_[d] - 1);
    cellOf_[i] = (idx[0] * dims_[1] + idx[1]) * dims_[2] + idx[2];
    ++cellStart_[cellOf_[i] + 1];
  }
  for (int c = 0; c < nCells; ++c) cellStart_[c + 1] += cellStart_[c];
  sorted_.resize(n);
  fill_.assign(cellStart_.begin(), cellStart_.end() - 1);
  for (int i = 0; i < n; ++i) sorted_[fill_[cellOf_[i]]++] = i;  // increasing i within a cell

  // bodies in cell order, contiguous (locality of the inner loops)
  sortedCentres_.resize(n);
  sortedRadii_.resize(n);
  for (int s = 0; s < n; ++s) {
    sortedCentres_[s] = centres[sorted_[s]];
    sortedRadii_[s] = radii[sorted_[s]];
  }
  auto test = [this](int s, int t) {
    const Scalar reach = sortedRadii_[s] + sortedRadii_[t];
    if ((sortedCentres_[s] - sortedCentres_[t]).squaredNorm() <= reach * reach) {
      const int i = sorted_[s], j = sorted_[t];
      pairs_.emplace_back(std::min(i, j), std::max(i, j));
    }
  };
  // each occupied cell with itself and its 13 "forward" neighbours (half of
  // the 26): every pair of cells, hence every pair of bodies, once
  static const int kForward[13][3] = {{0, 0, 1},  {0, 1, -1},  {0, 1, 0},  {0, 1, 1},  {1, -1, -1},
                                      {1, -1, 0}, {1, -1, 1},  {1, 0, -1}, {1, 0, 0},  {1, 0, 1},
                                      {1, 1, -1}, {1, 1, 0},   {1, 1, 1}};
  for (int c = 0; c < nCells; ++c) {
    const int s0 = cellStart_[c], s1 = cellStart_[c + 1];
    if (s0 == s1) continue;
    for (int s = s0; s < s1; ++s)
      for (int t = s + 1; t < s1; ++t) test(s, t);
    const int ci = c / (dims_[1] * dims_[2]), cj = (c / dims_[2]) % dims_[1], ck = c % dims_[2];
    for (const auto& o : kForward) {
      const int a = ci + o[0], b = cj + o[1], k = ck + o[2];
      if (a >= dims_[0] || b < 0 || b >= dims_[1] || k < 0 || k >= dims_[2]) continue;
      const int nc = (a * dims_[1] + b) * dims_[2] + k;
      const int t0 = cellStart_[nc], t1 = cellStart_[nc + 1];
      if (t0 == t1) continue;
      for (int s = s0; s < s1; ++s)
        for (int t = t0; t < t1; ++t) test(s, t);
    }
  }
  return pairs_;
}

}  // namespace collision
