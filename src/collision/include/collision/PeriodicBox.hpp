/**
 * @file PeriodicBox.hpp
 * @brief The periodic directions of a domain: a box whose opposite faces
 *        along some coordinate axes are identified (translational periodicity
 *        along x, y and/or z).
 *
 * Along a periodic axis d the domain is [origin_d, origin_d + length_d); a
 * body whose centre leaves it re-enters at the other side (wrap()), and the
 * image of a body shifted by a multiple of length_d along d is the same body.
 * Two bodies interact through the image of the second that is closest to the
 * first (minimum image: unique while every pair's interaction range is below
 * half of each period, checkRange()). An image is coded by one small integer
 * (imageCode): the multiples k_d in [-kMaxMultiple, kMaxMultiple] of each
 * period, 0 shift = kNoImage. Without periodic axes every shift is 0.
 *
 * Periods along coordinate axes only: the OpenFOAM side takes them from the
 * mesh's translational cyclic patches and stops the run for any other.
 */
#ifndef COLLISION_PERIODICBOX_HPP
#define COLLISION_PERIODICBOX_HPP

#include "collision/Types.hpp"

#include <array>

namespace collision {

class PeriodicBox {
 public:
  /// largest |multiple of a period| an image code holds (centres at most this many periods out of the box)
  static constexpr int kMaxMultiple = 2;
  static constexpr int kCodeBase = 2 * kMaxMultiple + 1;
  /// the code of the zero shift
  static constexpr int kNoImage = (kCodeBase * kCodeBase * kCodeBase) / 2;
  /// number of codes (0 .. kImageCodes - 1)
  static constexpr int kImageCodes = kCodeBase * kCodeBase * kCodeBase;

  /// No periodic axis.
  PeriodicBox() = default;
  /**
   * @param origin the box's lower corner (used along the periodic axes)
   * @param length the period along each axis (used where periodic is true)
   * @param periodic which axes are periodic
   * @throws std::invalid_argument on a non-finite origin, or a period that is not finite and > 0
   */
  PeriodicBox(const Vec3& origin, const Vec3& length, const std::array<bool, 3>& periodic);

  bool anyPeriodic() const { return periodic_[0] || periodic_[1] || periodic_[2]; }
  bool periodic(int axis) const { return periodic_[axis]; }
  const Vec3& origin() const { return origin_; }
  const Vec3& length() const { return length_; }

  /// The multiples k of each period with x - k L in [origin, origin + length) (up to the
  /// rounding of that difference; 0 along the other axes)
  /// @throws std::invalid_argument on a coordinate that is not finite or more than 1e9 periods out
  std::array<int, 3> wrapMultiples(const Vec3& x) const;
  /// x moved by whole periods into the box along each periodic axis: x - shift(wrapMultiples(x))
  Vec3 wrap(const Vec3& x) const;
  /// The multiples k of each period (0 along the others) that make d + k L shortest
  std::array<int, 3> minimumImage(const Vec3& d) const;
  /// The shift sum_d k_d length_d e_d
  Vec3 shift(const std::array<int, 3>& k) const;
  /// The shift of an image code
  Vec3 shift(int code) const { return shift(multiples(code)); }

  /// The code of the multiples k
  /// @throws std::out_of_range if some |k_d| > kMaxMultiple (a centre far out of the box)
  static int imageCode(const std::array<int, 3>& k);
  /// The multiples of a code
  static std::array<int, 3> multiples(int code);
  /// The code of the opposite shift
  static int opposite(int code) { return kImageCodes - 1 - code; }

  /**
   * The minimum image is the only one in reach if twice the largest
   * interaction range (bounding radius plus reach of two bodies) is below
   * each period.
   * @throws std::invalid_argument naming the axis, the period and the range otherwise
   */
  void checkRange(Scalar largestPairRange) const;

 private:
  Vec3 origin_ = Vec3::Zero();
  Vec3 length_ = Vec3::Zero();
  std::array<bool, 3> periodic_{false, false, false};
};

}  // namespace collision

#endif
