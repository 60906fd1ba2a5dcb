/**
 * @file Range.hpp
 * @brief The allowed values of a setting: an interval with open or closed
 *        bounds, the test and the text ("(0, 1]") that error messages show.
 *
 * Each setting's range is a named constant next to its default (the settings
 * structs), so that validate() and the OpenFOAM reader check and print the
 * same numbers.
 */
#ifndef COLLISION_RANGE_HPP
#define COLLISION_RANGE_HPP

#include "collision/Types.hpp"

#include <cmath>
#include <sstream>
#include <string>

namespace collision {

struct Range {
  Scalar lo = 0;
  Scalar hi = 0;
  bool loOpen = false;  ///< lo itself is excluded
  bool hiOpen = false;  ///< hi itself is excluded

  /// v is finite and within the bounds
  bool contains(Scalar v) const {
    return std::isfinite(v) && (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi);
  }

  /// "(lo, hi]", the bounds in the shortest form of a number ("1e-12", "0.5", "10000")
  std::string str() const {
    return (loOpen ? "(" : "[") + number(lo) + ", " + number(hi) + (hiOpen ? ")" : "]");
  }

  /// v as printed in str()
  static std::string number(Scalar v) {
    std::ostringstream os;
    os << v;
    return os.str();
  }
};

/// "name = value must be in <range>", the message of a value out of range.
inline std::string outOfRangeMessage(const std::string& name, Scalar value, const Range& range) {
  return name + " = " + Range::number(value) + " must be in " + range.str();
}

}  // namespace collision

#endif
