#include "ellipsoids/DistanceResult.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace ellipsoids {

const char* toString(DistanceStatus status) {
  switch (status) {
    case DistanceStatus::converged:
      return "converged";
    case DistanceStatus::overlapping:
      return "overlapping";
    case DistanceStatus::maxIterations:
      return "max-iterations";
    case DistanceStatus::failed:
      return "failed";
  }
  return "failed";
}

void DistanceOptions::validate() const {
  if (!(epsD > 0) || !std::isfinite(epsD)) {
    std::ostringstream os;
    os << "DistanceOptions: epsD must be finite and > 0, got " << epsD;
    throw std::invalid_argument(os.str());
  }
  if (maxIterations < 0) {
    throw std::invalid_argument("DistanceOptions: maxIterations must be >= 0 (0: method default), got " +
                                std::to_string(maxIterations));
  }
  if (useInitialDirection && !(initialDirection.allFinite() && initialDirection.norm() > 0)) {
    throw std::invalid_argument("DistanceOptions: initialDirection must be finite and non-zero");
  }
}

}  // namespace ellipsoids
