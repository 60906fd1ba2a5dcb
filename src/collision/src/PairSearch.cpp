#include "collision/PairSearch.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace collision {

const std::vector<CandidatePair>& PairSearch::find(const std::vector<Vec3>& centres,
                                                   const std::vector<Scalar>& radii,
                                                   const PeriodicBox& box,
                                                   const std::vector<char>* firsts) {
  pairs_.clear();
  const int n = static_cast<int>(centres.size());
  if (radii.size() != centres.size()) {
    throw std::invalid_argument("PairSearch: " + std::to_string(centres.size()) + " centres but " +
                                std::to_string(radii.size()) + " radii");
  }
  if (firsts && firsts->size() != centres.size()) {
    throw std::invalid_argument("PairSearch: " + std::to_string(centres.size()) + " centres but " +
                                std::to_string(firsts->size()) + " flags of first bodies");
  }
  if (n < 2) return pairs_;
  Scalar rMax = 0;
  for (int i = 0; i < n; ++i) {
    if (!centres[i].allFinite() || !(radii[i] > 0) || !std::isfinite(radii[i])) {
      throw std::invalid_argument("PairSearch: body " + std::to_string(i) +
                                  " has a non-finite centre or a radius that is not > 0");
    }
    rMax = std::max(rMax, radii[i]);
  }
  box.checkRange(2 * rMax);

  // the centres wrapped into the box along its periodic axes, and their extent
  wrapped_.resize(n);
  wrappedCentres_.resize(n);
  for (int i = 0; i < n; ++i) {
    wrapped_[i] = box.wrapMultiples(centres[i]);
    wrappedCentres_[i] = centres[i] - box.shift(wrapped_[i]);
  }
  Vec3 lo = wrappedCentres_[0], hi = wrappedCentres_[0];
  for (int i = 1; i < n; ++i) {
    lo = lo.cwiseMin(wrappedCentres_[i]);
    hi = hi.cwiseMax(wrappedCentres_[i]);
  }
  for (int d = 0; d < 3; ++d) {
    if (box.periodic(d)) {
      lo[d] = box.origin()[d];
      hi[d] = box.origin()[d] + box.length()[d];
    }
  }

  // a dense grid of cells of size >= 2 rMax (a pair can only meet in
  // neighbouring cells), with at most about 2 n + 27 cells in all so that
  // sparse or widely spread sets stay O(n) in memory and time; along a
  // periodic axis a whole number of cells spans the period
  const Vec3 span = hi - lo;
  auto cellsAlong = [&](int d, Scalar cell) {
    return box.periodic(d) ? std::max(Scalar(1), std::floor(span[d] / cell)) : std::floor(span[d] / cell) + 1;
  };
  Scalar cell = 2 * rMax;
  const Scalar maxCells = 2.0 * n + 27;
  for (int pass = 0; pass < 64; ++pass) {
    const Scalar cells = cellsAlong(0, cell) * cellsAlong(1, cell) * cellsAlong(2, cell);
    if (cells <= maxCells) break;
    cell *= std::cbrt(cells / maxCells) * 1.01;
  }
  if (!(cellsAlong(0, cell) * cellsAlong(1, cell) * cellsAlong(2, cell) <= maxCells)) {
    throw std::runtime_error("PairSearch: no cell size found for " + std::to_string(n) +
                             " bodies spanning " + std::to_string(span.maxCoeff()));
  }
  bool duplicates = false;  // a periodic axis of fewer than 3 cells meets a neighbour twice
  for (int d = 0; d < 3; ++d) {
    dims_[d] = static_cast<int>(cellsAlong(d, cell));
    cellSize_[d] = box.periodic(d) ? span[d] / dims_[d] : cell;
    duplicates = duplicates || (box.periodic(d) && dims_[d] < 3);
  }
  const int nCells = dims_[0] * dims_[1] * dims_[2];

  // counting sort of the bodies by cell
  cellOf_.resize(n);
  cellStart_.assign(nCells + 1, 0);
  for (int i = 0; i < n; ++i) {
    int idx[3];
    for (int d = 0; d < 3; ++d) {
      const int k = static_cast<int>((wrappedCentres_[i][d] - lo[d]) / cellSize_[d]);
      idx[d] = std::max(0, std::min(k, dims_[d] - 1));
    }
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
    sortedCentres_[s] = wrappedCentres_[sorted_[s]];
    sortedRadii_[s] = radii[sorted_[s]];
  }
  const bool periodic = box.anyPeriodic();
  auto test = [&](int s, int t) {
    if (s == t) return;  // (a body meets its own images only on a too small box: checkRange)
    const Scalar reach = sortedRadii_[s] + sortedRadii_[t];
    Vec3 d = sortedCentres_[t] - sortedCentres_[s];
    std::array<int, 3> k{0, 0, 0};
    if (periodic) {
      k = box.minimumImage(d);
      d += box.shift(k);
    }
    if (d.squaredNorm() > reach * reach) return;
    int i = sorted_[s], j = sorted_[t];
    if (!periodic) {
      pairs_.push_back({std::min(i, j), std::max(i, j), PeriodicBox::kNoImage});
      return;
    }
    // the shift of j's given centre: undo both wraps
    std::array<int, 3> m;
    for (int a = 0; a < 3; ++a) m[a] = k[a] + wrapped_[i][a] - wrapped_[j][a];
    int code = PeriodicBox::imageCode(m);
    if (i > j) {
      std::swap(i, j);
      code = PeriodicBox::opposite(code);
    }
    pairs_.push_back({i, j, code});
  };
  auto cellIndex = [&](const int idx[3]) { return (idx[0] * dims_[1] + idx[1]) * dims_[2] + idx[2]; };
  // the cell of an offset from cell c, or -1 outside a non-periodic grid
  auto neighbour = [&](int c, const int o[3]) {
    const int cIdx[3] = {c / (dims_[1] * dims_[2]), (c / dims_[2]) % dims_[1], c % dims_[2]};
    int nIdx[3];
    for (int d = 0; d < 3; ++d) {
      nIdx[d] = cIdx[d] + o[d];
      if (box.periodic(d)) {
        nIdx[d] = (nIdx[d] + dims_[d]) % dims_[d];
      } else if (nIdx[d] < 0 || nIdx[d] >= dims_[d]) {
        return -1;
      }
    }
    return cellIndex(nIdx);
  };
  if (firsts) {
    // each flagged body against the bodies of higher index in its cell and
    // its 26 neighbours (a cell met twice, on a periodic axis of fewer than 3
    // cells, is visited once)
    std::vector<int> seen;
    for (int s = 0; s < n; ++s) {
      const int i = sorted_[s];
      if (!(*firsts)[i]) continue;
      seen.clear();
      for (int a = -1; a <= 1; ++a)
        for (int b = -1; b <= 1; ++b)
          for (int c = -1; c <= 1; ++c) {
            const int o[3] = {a, b, c};
            const int nc = neighbour(cellOf_[i], o);
            if (nc < 0 || std::find(seen.begin(), seen.end(), nc) != seen.end()) continue;
            seen.push_back(nc);
            for (int t = cellStart_[nc]; t < cellStart_[nc + 1]; ++t) {
              if (sorted_[t] > i) test(s, t);
            }
          }
    }
    return pairs_;
  }
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
    for (const auto& o : kForward) {
      const int nc = neighbour(c, o);
      if (nc < 0) continue;
      const int t0 = cellStart_[nc], t1 = cellStart_[nc + 1];
      if (t0 == t1) continue;
      if (nc == c) {
        // a periodic axis of one cell: the cell is its own neighbour
        for (int s = s0; s < s1; ++s)
          for (int t = s + 1; t < s1; ++t) test(s, t);
        continue;
      }
      for (int s = s0; s < s1; ++s)
        for (int t = t0; t < t1; ++t) test(s, t);
    }
  }
  if (duplicates) {
    // neighbours met more than once: keep each pair once, in input order
    std::sort(pairs_.begin(), pairs_.end(), [](const CandidatePair& a, const CandidatePair& b) {
      return a.first != b.first ? a.first < b.first
                                : (a.second != b.second ? a.second < b.second : a.image < b.image);
    });
    pairs_.erase(std::unique(pairs_.begin(), pairs_.end()), pairs_.end());
  }
  return pairs_;
}

}  // namespace collision
