/**
 * @file Packing.hpp
 * @brief A periodic packing of ellipsoids in a cube, and the periodic
 *        neighbour search on it (cell list).
 *
 * Pure C++17 + Eigen (the geometry core's types); no OpenFOAM.
 *
 * Periodic conventions (one place, used by the generator, the tests and the
 * readers): the box is [0, L)^3; the minimum image of a separation d is
 * d - L round(d / L) component by component (std::round: halves away from
 * zero), so each component lies in [-L/2, L/2].
 */
#ifndef PACKING_PACKING_HPP
#define PACKING_PACKING_HPP

#include "ellipsoids/Ellipsoid.hpp"
#include "ellipsoids/Types.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

namespace packing {

struct Packing {
  double boxLength = 0;           ///< side L of the periodic cubic box (absolute length)
  double aspectRatio = 1;         ///< Ar of the mono-dispersed spheroids (metadata)
  double equivalentDiameter = 1;  ///< D_eq (metadata)
  double volumeFraction = 0;      ///< actual: N (pi/6) D_eq^3 / L^3
  std::uint64_t seed = 0;
  std::vector<ellipsoids::Ellipsoid> bodies;  ///< centres in [0, L)^3
};

/**
 * The Ellipsoid(semiAxes, centre, orientation), with the orientation nudged (by an ulp or two)
 * to a fixed point of the normalisation Ellipsoid's constructor applies: building the body
 * again from its own orientation() gives the same numbers, so a body written to a file and
 * read back is bit-identical. (That normalisation is compiled into the geometry library, with
 * its flags: the fixed point is found by calling the constructor itself.)
 */
ellipsoids::Ellipsoid storableBody(const ellipsoids::Vec3& semiAxes, const ellipsoids::Vec3& centre,
                                   const ellipsoids::Quat& orientation);

using ellipsoids::kPi;

/// N (pi/6) D^3 / L^3: the volume fraction of N equal-volume bodies of diameter D in a cube of side L.
inline double volumeFractionOf(std::size_t count, double equivalentDiameter, double boxLength) {
  const double d = equivalentDiameter, l = boxLength;
  return static_cast<double>(count) * (kPi / 6) * d * d * d / (l * l * l);
}

/**
 * The periodic translation that brings a separation vector to its minimum
 * image: -L round(d / L) per component (an integer multiple of L, exactly).
 * minimumImage(d, L) == d + periodicShift(d, L), bit for bit.
 */
inline ellipsoids::Vec3 periodicShift(const ellipsoids::Vec3& d, double boxLength) {
  return ellipsoids::Vec3(-boxLength * std::round(d.x() / boxLength),
                          -boxLength * std::round(d.y() / boxLength),
                          -boxLength * std::round(d.z() / boxLength));
}

/// minimum image of a separation vector in a periodic cube of side L (L > 0):
/// d - L round(d / L), each component in [-L/2, L/2].
inline ellipsoids::Vec3 minimumImage(const ellipsoids::Vec3& d, double boxLength) {
  return d + periodicShift(d, boxLength);
}

/// i < j; body j's centre + shift is its image nearest to body i
/// (shift = periodicShift(centre_j - centre_i, L): integer multiples of L).
struct NeighbourPair {
  int i;
  int j;
  ellipsoids::Vec3 shift;
};

/**
 * Every pair i < j whose minimum-image centre distance is <= cutoff, found
 * with a cell list (O(N)), sorted by (i, j). The distance test is
 * minimumImage(c_j - c_i, L).squaredNorm() <= cutoff^2, exactly as written
 * (a brute-force search with the same expression finds the same pairs).
 * Each pair appears once, with its minimum image, even when cutoff >= L/2
 * (then other images may also be within the cutoff: they are not listed).
 * Centres outside [0, L) are accepted (binned after wrapping).
 * @throws std::invalid_argument if boxLength is not finite and > 0, cutoff is
 *         not finite and >= 0, or there are more bodies than an int holds
 */
std::vector<NeighbourPair> neighbourPairs(const Packing& packing, double cutoff);

/// the body j moved to its image nearest to body i (same axes and orientation):
/// Ellipsoid(semiAxes_j, centre_j + pair.shift, orientation_j)
ellipsoids::Ellipsoid imageOf(const Packing& packing, const NeighbourPair& pair);

}  // namespace packing

#endif
