// A collision model of the tests built from its settings, the laws' parameters,
// the pair and wall model's name and the film correction's viscosity.
#ifndef COLLISION_TESTS_MODELSETUP_HPP
#define COLLISION_TESTS_MODELSETUP_HPP

#include "collision/CollisionModel.hpp"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace collision {

struct ModelSetup {
  CollisionSettings settings;
  InteractionParameters laws;
  /// the pair and the wall model
  std::string model = "springDashpot";
  /// > 0: a film correction with this viscosity; 0: none
  Scalar filmViscosity = 0;
  /// the film correction's factor on its damping estimate
  Scalar filmDampingScale = 1;
};

inline CollisionModel makeModel(const ModelSetup& s, std::vector<PlaneWall> walls) {
  return CollisionModel(s.settings, PairModel::New(s.model, s.laws), WallModel::New(s.model, s.laws),
                        std::move(walls),
                        s.filmViscosity > 0 ? std::make_unique<FilmCorrection>(s.filmViscosity,
                                                                               s.filmDampingScale)
                                            : nullptr);
}

}  // namespace collision

#endif
