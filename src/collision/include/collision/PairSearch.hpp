/**
 * @file PairSearch.hpp
 * @brief Candidate pairs of bodies from bounding spheres and a cell list
 *        (O(N) for bounded size ratios, not all pairs), periodic axes included.
 *
 * Each body i is a sphere of centre c_i and radius R_i (its largest semi-axis
 * plus its share of the interaction range). The cell size is the largest
 * 2 R_i (larger if the grid would have more than about 2N cells); a pair is a
 * candidate when |c_i - c_j - s| <= R_i + R_j for the shift s of the second
 * body's minimum image (0 without periodic axes). Bodies are binned into a
 * dense grid by a counting sort (O(N)), each pair of cells visited once (a
 * cell and its 13 forward neighbours). Along a periodic axis the grid spans
 * the period exactly and wraps around; the bodies are binned by their
 * wrapped centres, and the shift reported is the one that applies to the
 * centres given. Memory is reused from call to call. With flags for the
 * first bodies, each flagged body's cell and its 26 neighbours are visited
 * for the bodies of higher index.
 */
#ifndef COLLISION_PAIRSEARCH_HPP
#define COLLISION_PAIRSEARCH_HPP

#include "collision/PeriodicBox.hpp"
#include "collision/Types.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace collision {

/// Two bodies first < second that may interact, through the image of second
/// with this PeriodicBox image code (PeriodicBox::kNoImage without periodicity).
struct CandidatePair {
  int first = 0;
  int second = 0;
  int image = PeriodicBox::kNoImage;
  bool operator==(const CandidatePair& o) const {
    return first == o.first && second == o.second && image == o.image;
  }
};

class PairSearch {
 public:
  /**
   * The candidate pairs, each once, in an order that depends only on the
   * input (the same on every rank and after a restart; not sorted).
   * @param box the periodic axes (none by default)
   * @param firsts if given (one flag per body): only the pairs whose first
   *        body is flagged, found from those bodies' cells and their 26
   *        neighbours (a process's share of the pairs, WorkShare: the cost
   *        beyond the O(N) binning is that of the flagged bodies)
   * @throws std::invalid_argument on a non-finite centre, a radius that is
   *         not > 0, radii too large for the periods (PeriodicBox::checkRange),
   *         or flags that are not one per body
   */
  const std::vector<CandidatePair>& find(const std::vector<Vec3>& centres,
                                         const std::vector<Scalar>& radii,
                                         const PeriodicBox& box = PeriodicBox(),
                                         const std::vector<char>* firsts = nullptr);

 private:
  int dims_[3] = {1, 1, 1};
  Scalar cellSize_[3] = {1, 1, 1};
  std::vector<int> cellOf_;     ///< cell of each body
  std::vector<int> cellStart_;  ///< first slot of each cell in sorted_ (size cells + 1)
  std::vector<int> fill_;       ///< scratch of the counting sort
  std::vector<int> sorted_;     ///< bodies by cell
  std::vector<Vec3> sortedCentres_;  ///< wrapped centres
  std::vector<Scalar> sortedRadii_;
  std::vector<std::array<int, 3>> wrapped_;  ///< periods each centre was moved by
  std::vector<Vec3> wrappedCentres_;         ///< by body
  std::vector<CandidatePair> pairs_;
};

}  // namespace collision

#endif
