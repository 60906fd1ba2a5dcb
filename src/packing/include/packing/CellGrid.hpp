/**
 * @file CellGrid.hpp
 * @brief The periodic cell grid behind the neighbour searches: m^3 cubic cells
 *        of side L/m >= the search radius, so that every point within the
 *        radius of a point (minimum image) lies in its cell or one of the 26
 *        around it (periodically). For m < 3 those 27 cells repeat; the
 *        neighbour list of a cell is then deduplicated.
 */
#ifndef PACKING_CELLGRID_HPP
#define PACKING_CELLGRID_HPP

#include "ellipsoids/Types.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace packing {

class CellGrid {
 public:
  /**
   * @param boxLength   L > 0
   * @param minCellSide the search radius (>= 0): cells are at least this wide
   * @param maxPerSide  upper bound on m (bounds memory for tiny radii), >= 1
   */
  CellGrid(double boxLength, double minCellSide, int maxPerSide) : boxLength_(boxLength) {
    if (!(boxLength > 0) || !std::isfinite(boxLength)) {
      throw std::invalid_argument("CellGrid: box length must be finite and > 0");
    }
    double m = minCellSide > 0 ? std::floor(boxLength / minCellSide) : double(maxPerSide);
    m = std::min(m, double(std::max(1, maxPerSide)));
    perSide_ = std::max(1, static_cast<int>(m));
    // rounding: make sure L/m >= minCellSide (floor may be one too many in floating point)
    while (perSide_ > 1 && boxLength / perSide_ < minCellSide) --perSide_;
    scale_ = perSide_ / boxLength;
    buildStencil();
  }

  int perSide() const { return perSide_; }
  int cellCount() const { return perSide_ * perSide_ * perSide_; }
  double boxLength() const { return boxLength_; }

  /// cell of a point (wrapped into [0, L) first)
  int cellOf(const ellipsoids::Vec3& x) const {
    return index(coordinate(x.x()), coordinate(x.y()), coordinate(x.z()));
  }

  /// the distinct cells within one cell of `cell` (periodically), itself included
  const std::vector<int>& neighbours(int cell) const {
    return stencils_[static_cast<std::size_t>(cell)];
  }

 private:
  int coordinate(double x) const {
    double w = x - boxLength_ * std::floor(x / boxLength_);  // [0, L], L only by rounding
    int c = static_cast<int>(w * scale_);
    return std::clamp(c, 0, perSide_ - 1);
  }
  int index(int i, int j, int k) const { return (i * perSide_ + j) * perSide_ + k; }
  int wrap(int i) const { return ((i % perSide_) + perSide_) % perSide_; }

  void buildStencil() {
    stencils_.resize(static_cast<std::size_t>(cellCount()));
    for (int i = 0; i < perSide_; ++i)
      for (int j = 0; j < perSide_; ++j)
        for (int k = 0; k < perSide_; ++k) {
          std::vector<int>& s = stencils_[static_cast<std::size_t>(index(i, j, k))];
          s.reserve(27);
          for (int di = -1; di <= 1; ++di)
            for (int dj = -1; dj <= 1; ++dj)
              for (int dk = -1; dk <= 1; ++dk) s.push_back(index(wrap(i + di), wrap(j + dj), wrap(k + dk)));
          std::sort(s.begin(), s.end());
          s.erase(std::unique(s.begin(), s.end()), s.end());
        }
  }

  double boxLength_;
  int perSide_ = 1;
  double scale_ = 1;
  std::vector<std::vector<int>> stencils_;
};

}  // namespace packing

#endif
