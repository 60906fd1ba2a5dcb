/**
 * @file PairSearch.hpp
 * @brief Candidate pairs of bodies from bounding spheres and a cell list
 *        (O(N) for bounded size ratios, not all pairs).
 *
 * Each body i is a sphere of centre c_i and radius R_i (its largest semi-axis
 * plus its share of the interaction range). The cell size is the largest
 * 2 R_i (larger if the grid would have more than about 2N cells); a pair is a
 * candidate when |c_i - c_j| <= R_i + R_j. Bodies are binned into a dense
 * grid by a counting sort (O(N)), each pair of cells visited once (a cell
 * and its 13 forward neighbours). Memory is reused from call to call.
 */
#ifndef COLLISION_PAIRSEARCH_HPP
#define COLLISION_PAIRSEARCH_HPP

#include "collision/Types.hpp"

#include <cstdint>
#include <utility>
#include <vector>

namespace collision {

class PairSearch {
 public:
  /**
   * The candidate pairs (i < j), each once, in an order that depends only on
   * the input (the same on every rank and after a restart; not sorted).
   * @throws std::invalid_argument on a non-finite centre or a radius that is not > 0
   */
  const std::vector<std::pair<int, int>>& find(const std::vector<Vec3>& centres,
                                               const std::vector<Scalar>& radii);

 private:
  int dims_[3] = {1, 1, 1};
  std::vector<int> cellOf_;     ///< cell of each body
  std::vector<int> cellStart_;  ///< first slot of each cell in sorted_ (size cells + 1)
  std::vector<int> fill_;       ///< scratch of the counting sort
  std::vector<int> sorted_;     ///< bodies by cell
  std::vector<Vec3> sortedCentres_;
  std::vector<Scalar> sortedRadii_;
  std::vector<std::pair<int, int>> pairs_;
};

}  // namespace collision

#endif
