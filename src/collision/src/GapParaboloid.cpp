#include "collision/GapParaboloid.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace collision {

GapParaboloid GapParaboloid::fromCurvatureTensors(const Mat3& S1, const Mat3& S2, const Vec3& n) {
  const Mat3 P = Mat3::Identity() - n * n.transpose();
  const Mat3 K = P * (S1 + S2) * P;
  // on the plane normal to n: trace k1 + k2, and k1 k2 from the invariants
  // of the 3x3 tensor whose third eigenvalue (along n) is zero
  const Scalar trace = K.trace();
  const Scalar product = (trace * trace - (K * K).trace()) / 2;
  const Scalar half = std::sqrt(std::max(trace * trace / 4 - product, Scalar(0)));
  GapParaboloid g;
  g.k2 = trace / 2 + half;
  g.k1 = g.k2 > 0 ? product / g.k2 : 0;  // product / k2: no cancellation
  if (!(g.k1 > 0) || !std::isfinite(g.k2)) {
    std::ostringstream msg;
    msg << "GapParaboloid: the gap's curvatures must be positive and finite, got k1 = " << g.k1
        << ", k2 = " << g.k2 << " (two convex surfaces, at most one of them a plane)";
    throw std::invalid_argument(msg.str());
  }
  return g;
}

Scalar GapParaboloid::squeezeRadius() const {
  return std::sqrt(2 / (std::sqrt(k1 * k2) * (k1 + k2)));
}

}  // namespace collision
