#include "collision/PeriodicBox.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace collision {

namespace {
const char* const kAxis[3] = {"x", "y", "z"};
}  // namespace

PeriodicBox::PeriodicBox(const Vec3& origin, const Vec3& length, const std::array<bool, 3>& periodic)
    : origin_(origin), length_(length), periodic_(periodic) {
  for (int d = 0; d < 3; ++d) {
    if (!periodic_[d]) continue;
    if (!std::isfinite(origin_[d]) || !(length_[d] > 0) || !std::isfinite(length_[d])) {
      std::ostringstream os;
      os << "PeriodicBox: the period along " << kAxis[d] << " must be finite and > 0 with a finite"
         << " origin, got origin " << origin_[d] << ", period " << length_[d];
      throw std::invalid_argument(os.str());
    }
  }
}

std::array<int, 3> PeriodicBox::wrapMultiples(const Vec3& x) const {
  std::array<int, 3> k{0, 0, 0};
  for (int d = 0; d < 3; ++d) {
    if (!periodic_[d]) continue;
    const Scalar q = std::floor((x[d] - origin_[d]) / length_[d]);
    if (!(std::abs(q) < 1e9)) {
      std::ostringstream os;
      os << "PeriodicBox: coordinate " << kAxis[d] << " = " << x[d] << " is not finite or absurdly far"
         << " from the periodic box (origin " << origin_[d] << ", period " << length_[d] << ")";
      throw std::invalid_argument(os.str());
    }
    k[d] = static_cast<int>(q);
    // the quotient's rounding can put x - k L just outside [origin, origin + L)
    const Scalar w = x[d] - k[d] * length_[d];
    if (w >= origin_[d] + length_[d]) ++k[d];
    if (w < origin_[d]) --k[d];
  }
  return k;
}

Vec3 PeriodicBox::wrap(const Vec3& x) const { return x - shift(wrapMultiples(x)); }

std::array<int, 3> PeriodicBox::minimumImage(const Vec3& d) const {
  std::array<int, 3> k{0, 0, 0};
  for (int a = 0; a < 3; ++a) {
    if (periodic_[a]) k[a] = -static_cast<int>(std::lround(d[a] / length_[a]));
  }
  return k;
}

Vec3 PeriodicBox::shift(const std::array<int, 3>& k) const {
  Vec3 s = Vec3::Zero();
  for (int a = 0; a < 3; ++a) {
    if (periodic_[a]) s[a] = k[a] * length_[a];
  }
  return s;
}

int PeriodicBox::imageCode(const std::array<int, 3>& k) {
  for (int a = 0; a < 3; ++a) {
    if (k[a] < -kMaxMultiple || k[a] > kMaxMultiple) {
      std::ostringstream os;
      os << "PeriodicBox: an image " << k[a] << " periods away along " << kAxis[a]
         << " (at most " << kMaxMultiple << "): a body centre far outside the periodic box"
         << " (centres are wrapped into it every step)";
      throw std::out_of_range(os.str());
    }
  }
  return ((k[0] + kMaxMultiple) * kCodeBase + (k[1] + kMaxMultiple)) * kCodeBase + (k[2] + kMaxMultiple);
}

std::array<int, 3> PeriodicBox::multiples(int code) {
  return {code / (kCodeBase * kCodeBase) - kMaxMultiple, (code / kCodeBase) % kCodeBase - kMaxMultiple,
          code % kCodeBase - kMaxMultiple};
}

void PeriodicBox::checkRange(Scalar largestPairRange) const {
  for (int d = 0; d < 3; ++d) {
    if (periodic_[d] && !(2 * largestPairRange < length_[d])) {
      std::ostringstream os;
      os << "PeriodicBox: the period along " << kAxis[d] << " (" << length_[d]
         << ") must exceed twice the largest interaction range of a pair (" << largestPairRange
         << ": two bounding radii plus the lubrication and film reach), so that a pair meets"
         << " through one image only; use a larger box or smaller bodies";
      throw std::invalid_argument(os.str());
    }
  }
}

}  // namespace collision
