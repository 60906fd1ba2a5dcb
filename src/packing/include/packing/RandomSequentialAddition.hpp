/**
 * @file RandomSequentialAddition.hpp
 * @brief Random sequential addition (RSA) of mono-dispersed spheroids in a
 *        periodic cube (founding paper, section 4.1.1).
 *
 * Equal-volume spheroids: a = Ar^(2/3) D/2 along the body x axis,
 * b = c = Ar^(-1/3) D/2. Body after body, a candidate gets a position uniform
 * in [0, L)^3 and an orientation uniform on SO(3); it is kept if the Jia et al.
 * test says "separated" against every body already placed (minimum images;
 * touching counts as overlap), otherwise a new candidate is drawn, at most
 * maxAttemptsPerBody times. N = round(alpha l^3 6 / pi).
 *
 * Reproducible: std::mt19937_64 seeded with `seed` (its output is fixed by the
 * C++ standard), converted to [0, 1) as (x >> 11) 2^-53; position first
 * (x, y, z: L u), then the orientation by Marsaglia's rejection method on S^3
 * (only +, -, *, /, sqrt: correctly rounded IEEE operations, no libm
 * transcendental; this library is compiled with -ffp-contract=off), so the
 * same seed gives the same stream of candidates on any IEEE-754 machine, with
 * no std distribution involved. Two things are computed by the geometry core
 * and follow its build: the stored orientation (storableBody, within an ulp or
 * two of the drawn one) and the Jia test's decision, which only a pair within
 * ~1e-10 of touching could see change with other compiler flags or another
 * CPU (the core is built with -march=native by default).
 *
 * Every candidate drawn counts as an attempt (also those rejected at once in a
 * blocked voxel); a body that needs more than maxAttemptsPerBody throws.
 *
 * With walls, a candidate must also lie inside the cube, its support along each
 * axis (sqrt(e^T U diag(a^2) U^T e)) at least wallClearance D_eq from the faces;
 * the draws are the same, so the packing is the periodic one's candidate stream
 * filtered by the walls.
 *
 * Cost: a cell list (cells >= 2 a_max (1 + 1e-6)), cheap exact filters
 * before the Jia test (bounding and inscribed spheres, the body inflated by
 * a_min, a separating plane normal to the centre line) and a bit per voxel of
 * side a_min/2 flagging the voxels where no candidate can fit, whatever its
 * orientation. Each filter decides only with a relative margin of 1e-6, so the
 * result is the packing a plain "Jia-test against every body" loop would give
 * with the same draws (tests/packing/RsaTest.cpp compares the two).
 * Memory: the bodies, plus at most 32 MB of voxel flags.
 */
#ifndef PACKING_RANDOMSEQUENTIALADDITION_HPP
#define PACKING_RANDOMSEQUENTIALADDITION_HPP

#include "packing/Packing.hpp"

#include <cstddef>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

namespace packing {

struct RsaOptions {
  double aspectRatio = 1;          ///< > 0 (finite)
  double boxLengthRelative = 10;   ///< l = L / D_eq, > 4 a_max / D_eq = 2 max(Ar^(2/3), Ar^(-1/3))
  double volumeFraction = 0.1;     ///< (0, 0.3]; 0.25 is the practical RSA limit here
  std::uint64_t seed = 1;
  double equivalentDiameter = 1;   ///< > 0 (finite)
  long maxAttemptsPerBody = 1000000;  ///< >= 1
  bool progress = false;           ///< bodies placed / total on stderr
  /// walls: every body lies entirely inside the cube, clear of its faces by
  /// wallClearance D_eq (a candidate reaching further is drawn again), e.g. for a
  /// column with walls; the packing is still separated across the periodic
  /// images too, so it stays a valid periodic packing
  bool walls = false;
  double wallClearance = 0;        ///< >= 0, relative to D_eq; with walls only
};

/// What a run did (the optional output of randomSequentialAddition).
struct RsaStatistics {
  std::size_t bodies = 0;              ///< N
  std::uint64_t attempts = 0;          ///< candidates drawn, over all bodies
  long maxAttemptsForOneBody = 0;      ///< the most candidates one body needed
  std::uint64_t jiaTests = 0;          ///< pairs decided by the Jia et al. test (not by a filter)
  std::uint64_t voxelRejections = 0;   ///< candidates rejected at once: in a voxel known to be blocked
  std::uint64_t deadVoxels = 0;        ///< voxels found blocked whatever the orientation
  std::uint64_t wallRejections = 0;    ///< candidates reaching closer to a wall than allowed (walls)
  double seconds = 0;                  ///< wall time of the placement
};

/// std::invalid_argument naming the offending RsaOptions member.
class InvalidRsaOption : public std::invalid_argument {
 public:
  InvalidRsaOption(std::string option, const std::string& message)
      : std::invalid_argument(message), option_(std::move(option)) {}
  /// the RsaOptions member: "aspectRatio", "boxLengthRelative", "volumeFraction",
  /// "equivalentDiameter", "maxAttemptsPerBody" or "wallClearance"
  const std::string& option() const { return option_; }

 private:
  std::string option_;
};

/// Smallest valid l (exclusive bound): the box must exceed twice the longest
/// body length 2 a_max (1 + 1e-6), so that the minimum image is the only image
/// that can touch: 4 a_max (1 + 1e-6) / D_eq.
double minimumBoxLengthRelative(double aspectRatio);

/// N = round(alpha l^3 6 / pi) (no validation).
std::size_t rsaBodyCount(const RsaOptions& options);

/// @throws InvalidRsaOption (a std::invalid_argument) naming the option and the allowed range
void validate(const RsaOptions& options);

/**
 * @throws std::invalid_argument (InvalidRsaOption) for invalid options (message
 *         names the option and the allowed range),
 *         std::runtime_error when a body cannot be placed (message names the
 *         body index, the attempts and the volume fraction reached)
 */
Packing randomSequentialAddition(const RsaOptions& options);

/// The same, also reporting what the run did (statistics may be null).
Packing randomSequentialAddition(const RsaOptions& options, RsaStatistics* statistics);

/// Deterministic conversions of std::mt19937_64's raw output (exposed for the tests).
namespace random {

/// (x >> 11) 2^-53: uniform on the 2^53 doubles k 2^-53 of [0, 1).
inline double uniform01(std::mt19937_64& engine) {
  return static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

/**
 * Uniform unit quaternion (w, x, y, z), hence uniform rotation on SO(3)
 * (Marsaglia 1972: (x1, x2) and (x3, x4) uniform in the unit disc,
 * q = (x1, x2, x3 t, x4 t), t = sqrt((1 - s1) / s2)): unit to rounding.
 * The bodies keep storableBody(semiAxes, centre, q), q within an ulp or two.
 * @throws std::runtime_error if 64 draws in a row fall outside the disc
 *         (probability 1e-43: a broken engine)
 */
ellipsoids::Quat orientation(std::mt19937_64& engine);

}  // namespace random

}  // namespace packing

#endif
