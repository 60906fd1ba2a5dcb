/**
 * @file WallModel.hpp
 * @brief The interaction of a body and a plane wall, selected by name (as ESI's
 *        PairCollision wallModel).
 *
 * Usage: WallModel::New(name, parameters), name one of names():
 * | name                    | normal contact       | friction | lubrication |
 * |-------------------------|----------------------|----------|-------------|
 * | springDashpot           | SpringDashpotContact | Coulomb  | none        |
 * | lubricatedSpringDashpot | SpringDashpotContact | Coulomb  | Stokes (wallActivation) |
 *
 * See also: PairModel, InteractionModel, CollisionModel.
 */
#ifndef COLLISION_WALLMODEL_HPP
#define COLLISION_WALLMODEL_HPP

#include "collision/InteractionModel.hpp"

namespace collision {

class WallModel : public InteractionModel {
 public:
  using InteractionModel::InteractionModel;

  /// the names New() builds
  static const std::vector<std::string>& names();

  /// @throws std::invalid_argument on an unknown name (listing names()) or invalid parameters
  static std::unique_ptr<WallModel> New(const std::string& name,
                                        const InteractionParameters& parameters);
};

}  // namespace collision

#endif
