/**
 * @file PairTable.hpp
 * @brief Reading ellipsoid pairs from CSV for ellipsoidDistance (pure C++).
 *
 * Header (exactly these 20 names, any order is NOT accepted):
 *   a1,b1,c1,x1,y1,z1,qw1,qx1,qy1,qz1,a2,b2,c2,x2,y2,z2,qw2,qx2,qy2,qz2
 * One pair a row; blank lines are skipped; row numbers count data rows from 1.
 */
#ifndef ELLIPSOIDDISTANCE_PAIRTABLE_HPP
#define ELLIPSOIDDISTANCE_PAIRTABLE_HPP

#include "ellipsoids/Ellipsoid.hpp"

#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

namespace pairtable {

struct Pair {
  int row;  ///< 1-based data row
  ellipsoids::Ellipsoid e1;
  ellipsoids::Ellipsoid e2;
};

/// Error in the input: the message names the source, row, line and column.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The expected header columns.
const std::vector<std::string>& columns();

/**
 * Reads every pair. A quaternion within 1e-6 of unit norm is normalised
 * silently.
 * @param source name used in messages (file path or "standard input")
 * @throws InputError on a bad header, a malformed row (wrong number of fields,
 *         a field that is not a finite number), a semi-axis, centre or
 *         elongation outside ellipsoids::SupportedRange, or a quaternion
 *         farther than 1e-6 from unit norm
 */
std::vector<Pair> read(std::istream& in, const std::string& source);

}  // namespace pairtable

#endif
