/**
 * @file PairSearch.hpp
 * @brief Candidate pairs of bodies from bounding spheres and a cell list
 *        (O(N) for bounded size ratios, not all pairs).
 *
 * Each body i is a sphere of centre c_i and radius R_i (its largest semi-axis
 * plus its share of the interaction range). The cell size is the largest
 * 2 R_i; a pair is a candidate when |c_i - c_j| <= R_i + R_j. Bodies are
 * binned by cell (sorted keys), each pair visited once from the 27
 * neighbouring cells. Memory is reused from call to call.
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
   * The candidate pairs (i < j), in increasing (i, j) order.
   * @throws std::invalid_argument on a non-finite centre or a radius that is not > 0
   */
  const std::vector<std::pair<int, int>>& find(const std::vector<Vec3>& centres,
                                               const std::vector<Scalar>& radii);

 private:
  struct Entry {
    std::int64_t key;
    int body;
  };
  std::vector<Entry> entries_;
  std::vector<std::pair<int, int>> pairs_;
};

}  // namespace collision

#endif
