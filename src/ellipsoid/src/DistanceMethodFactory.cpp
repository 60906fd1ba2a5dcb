#include "ellipsoids/AutoDistance.hpp"
#include "ellipsoids/DistanceMethod.hpp"
#include "ellipsoids/DualNewton.hpp"
#include "ellipsoids/ExteriorPenalty.hpp"
#include "ellipsoids/Gjk.hpp"
#include "ellipsoids/JainDistance.hpp"
#include "ellipsoids/MovingBalls.hpp"
#include "ellipsoids/NewtonCoulomb.hpp"

#include <functional>
#include <stdexcept>
#include <utility>

namespace ellipsoids {

namespace {

using Factory = std::function<std::unique_ptr<DistanceMethod>()>;

template <class Method>
std::pair<std::string, Factory> entry(const char* name) {
  return {name, [] { return std::unique_ptr<DistanceMethod>(new Method()); }};
}

/// The one list of methods: name on the command line -> constructor (paper's order, then ours).
const std::vector<std::pair<std::string, Factory>>& registry() {
  static const std::vector<std::pair<std::string, Factory>> methods = {
      entry<MovingBalls>("movingBalls"),     entry<Gjk>("gjk"),
      entry<NewtonCoulomb>("newtonCoulomb"), entry<ExteriorPenalty>("exteriorPenalty"),
      entry<JainDistance>("jain"),           entry<DualNewton>("dual"),
      entry<AutoDistance>("auto"),
      {"paper", [] { return std::unique_ptr<DistanceMethod>(AutoDistance::paper()); }}};
  return methods;
}

}  // namespace

const std::vector<std::string>& distanceMethodNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& m : registry()) n.push_back(m.first);
    return n;
  }();
  return names;
}

std::unique_ptr<DistanceMethod> makeDistanceMethod(const std::string& name) {
  for (const auto& m : registry()) {
    if (m.first == name) return m.second();
  }
  std::string valid;
  for (const auto& n : distanceMethodNames()) valid += (valid.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown distance method '" + name + "'; valid methods: " + valid);
}

}  // namespace ellipsoids
