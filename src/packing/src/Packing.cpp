#include "packing/Packing.hpp"

#include "packing/CellGrid.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace packing {

using ellipsoids::Ellipsoid;
using ellipsoids::Vec3;

std::vector<NeighbourPair> neighbourPairs(const Packing& packing, double cutoff) {
  const double L = packing.boxLength;
  if (!(L > 0) || !std::isfinite(L)) {
    std::ostringstream os;
    os << "neighbourPairs: boxLength must be finite and > 0, got " << L;
    throw std::invalid_argument(os.str());
  }
  if (!(cutoff >= 0) || !std::isfinite(cutoff)) {
    std::ostringstream os;
    os << "neighbourPairs: cutoff must be finite and >= 0, got " << cutoff;
    throw std::invalid_argument(os.str());
  }
  const std::size_t n = packing.bodies.size();
  if (n > static_cast<std::size_t>(INT_MAX)) {
    throw std::invalid_argument("neighbourPairs: more bodies than an int can index");
  }
  std::vector<NeighbourPair> pairs;
  if (n < 2) return pairs;

  // about one body per cell at most: bounded memory whatever the cutoff
  const int maxPerSide =
      std::min(1024, std::max(1, 2 * static_cast<int>(std::ceil(std::cbrt(double(n))))));
  const CellGrid grid(L, cutoff, maxPerSide);

  // bodies by cell (counting sort: each cell lists its bodies in increasing order)
  const std::size_t cells = static_cast<std::size_t>(grid.cellCount());
  std::vector<int> cellOfBody(n), start(cells + 1, 0), members(n);
  for (std::size_t b = 0; b < n; ++b) {
    cellOfBody[b] = grid.cellOf(packing.bodies[b].centre());
    ++start[static_cast<std::size_t>(cellOfBody[b]) + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) start[c + 1] += start[c];
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (std::size_t b = 0; b < n; ++b) members[static_cast<std::size_t>(fill[static_cast<std::size_t>(cellOfBody[b])]++)] = static_cast<int>(b);
  }

  const double cutoff2 = cutoff * cutoff;
  for (std::size_t bi = 0; bi < n; ++bi) {
    const int i = static_cast<int>(bi);
    const Vec3& ci = packing.bodies[bi].centre();
    for (int c : grid.neighbours(cellOfBody[bi])) {
      const std::size_t cc = static_cast<std::size_t>(c);
      for (int m = start[cc]; m < start[cc + 1]; ++m) {
        const int j = members[static_cast<std::size_t>(m)];
        if (j <= i) continue;
        const Vec3 d = packing.bodies[static_cast<std::size_t>(j)].centre() - ci;
        const Vec3 shift = periodicShift(d, L);
        if ((d + shift).squaredNorm() <= cutoff2) pairs.push_back(NeighbourPair{i, j, shift});
      }
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const NeighbourPair& p, const NeighbourPair& q) {
    return p.i != q.i ? p.i < q.i : p.j < q.j;
  });
  return pairs;
}

Ellipsoid storableBody(const Vec3& semiAxes, const Vec3& centre, const ellipsoids::Quat& orientation) {
  // A fixed point q = normalise(q) has a computed squared norm of 1 or 1 + 2^-52 (sqrt then
  // rounds to 1). Renormalising usually gets there at once; it can also cycle between a
  // quaternion a little long and one a little short. Then step the larger components by a
  // few ulps (each changes the squared norm by about its granularity) until one is fixed.
  auto fixed = [&](const ellipsoids::Quat& q) {
    return Ellipsoid(semiAxes, centre, q).orientation().coeffs() == q.coeffs();
  };
  Ellipsoid body(semiAxes, centre, orientation);
  for (int k = 0; k < 3; ++k) {
    const Ellipsoid again(semiAxes, centre, body.orientation());
    if (again.orientation().coeffs() == body.orientation().coeffs()) return body;
    body = again;
  }
  const ellipsoids::Quat start = body.orientation();
  int order[4] = {0, 1, 2, 3};  // coefficient indices (x y z w), largest magnitude first
  std::sort(order, order + 4, [&](int a, int b) {
    return std::abs(start.coeffs()[a]) > std::abs(start.coeffs()[b]);
  });
  for (int which = 0; which < 2; ++which) {
    for (int steps = 1; steps <= 8; ++steps) {
      for (double direction : {1.0, -1.0}) {
        ellipsoids::Quat q = start;
        double& c = q.coeffs()[order[which]];
        for (int s = 0; s < steps; ++s) c = std::nextafter(c, direction * HUGE_VAL);
        if (fixed(q)) return Ellipsoid(semiAxes, centre, q);
      }
    }
  }
  return body;  // not reached in practice (tests/packing checks many draws)
}

Ellipsoid imageOf(const Packing& packing, const NeighbourPair& pair) {
  if (pair.j < 0 || static_cast<std::size_t>(pair.j) >= packing.bodies.size()) {
    std::ostringstream os;
    os << "imageOf: body index " << pair.j << " out of range [0, " << packing.bodies.size() << ")";
    throw std::out_of_range(os.str());
  }
  const Ellipsoid& body = packing.bodies[static_cast<std::size_t>(pair.j)];
  return Ellipsoid(body.semiAxes(), body.centre() + pair.shift, body.orientation());
}

}  // namespace packing
