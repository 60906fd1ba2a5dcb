/**
 * @file PackingQueries.hpp
 * @brief The distance queries of a random packing (founding paper section 4.1.2)
 *        and their reference distances.
 *
 * Queries: every pair whose minimum-image centre distance passes the
 * augmented bounding-sphere test of eq. 4.2, |r1 - r2| <= 2 max(a, b) + eps_al R_eq
 * (eps_al = 0.2), with body 2 moved to its image nearest to body 1.
 * Reference: the dual method and GJK, both with a certified bracket of
 * 1e-11 R_eq (the certified floor of Ar 6 pairs at coordinates up to 40 D_eq
 * is about 5e-13 R_eq: the rounding allowance grows with the elongation,
 * CertifiedBracket.hpp); the reference is the dual answer and its uncertainty
 * the larger of the two brackets and their difference.
 */
#ifndef DISTANCEBENCHMARK_PACKINGQUERIES_HPP
#define DISTANCEBENCHMARK_PACKINGQUERIES_HPP

#include "ellipsoids/DistanceMethod.hpp"
#include "packing/Packing.hpp"
#include "packing/RandomSequentialAddition.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace benchmark_support {

using ellipsoids::DistanceOptions;
using ellipsoids::DistanceResult;
using ellipsoids::DistanceStatus;
using ellipsoids::Ellipsoid;
using ellipsoids::Scalar;

struct Query {
  Ellipsoid e1;
  Ellipsoid e2;  ///< the image of body 2 nearest to body 1
  int i, j;      ///< body indices in the packing
  Scalar reference = 0;        ///< reference distance
  Scalar referenceError = 0;   ///< its uncertainty (bracket widths and disagreement)
};

/// Equal-volume radius of the packing's bodies.
inline Scalar equivalentRadius(const packing::Packing& p) { return p.equivalentDiameter / 2; }

/// Queries of eq. 4.2 with eps_al = 0.2.
inline std::vector<Query> makeQueries(const packing::Packing& p, double epsAl = 0.2) {
  std::vector<Query> qs;
  if (p.bodies.empty()) return qs;
  const Ellipsoid& b = p.bodies.front();
  const double cutoff = 2 * b.maxSemiAxis() + epsAl * equivalentRadius(p);
  for (const packing::NeighbourPair& np : packing::neighbourPairs(p, cutoff)) {
    qs.push_back(Query{p.bodies[np.i], packing::imageOf(p, np), np.i, np.j});
  }
  return qs;
}

/// Reference distances; returns the number of pairs whose two references
/// disagree beyond their brackets (expected 0).
inline int computeReferences(std::vector<Query>& qs, Scalar rEq) {
  const auto dual = ellipsoids::makeDistanceMethod("dual");
  const auto gjk = ellipsoids::makeDistanceMethod("gjk");
  DistanceOptions o;
  o.epsD = 1e-11 * rEq;
  o.stopRule = ellipsoids::StopRule::certified;
  int disagreements = 0;
  for (Query& q : qs) {
    const DistanceResult a = dual->distance(q.e1, q.e2, o);
    const DistanceResult b = gjk->distance(q.e1, q.e2, o);
    q.reference = a.distance;
    q.referenceError = std::max({a.bracketWidth(), b.bracketWidth(), std::abs(a.distance - b.distance)});
    const bool consistent = a.lower <= b.upper && b.lower <= a.upper;
    if (!consistent || a.status != DistanceStatus::converged || b.status != DistanceStatus::converged) {
      ++disagreements;
    }
  }
  return disagreements;
}

/// The packing of the paper's section 4.1.1 for (Ar, alpha, l), D_eq = 1.
inline packing::Packing makePacking(double ar, double alpha, double l, std::uint64_t seed) {
  packing::RsaOptions o;
  o.aspectRatio = ar;
  o.boxLengthRelative = l;
  o.volumeFraction = alpha;
  o.seed = seed;
  o.equivalentDiameter = 1;
  return packing::randomSequentialAddition(o);
}

}  // namespace benchmark_support

#endif
