/**
 * @file PairModel.hpp
 * @brief The interaction of two bodies, selected by name (as ESI's
 *        PairCollision pairModel).
 *
 * Usage: PairModel::New(name, parameters), name one of names():
 * | name                    | normal contact       | friction | lubrication |
 * |-------------------------|----------------------|----------|-------------|
 * | springDashpot           | SpringDashpotContact | Coulomb  | none        |
 * | lubricatedSpringDashpot | SpringDashpotContact | Coulomb  | Stokes (pairActivation) |
 *
 * See also: WallModel, InteractionModel, CollisionModel.
 */
#ifndef COLLISION_PAIRMODEL_HPP
#define COLLISION_PAIRMODEL_HPP

#include "collision/InteractionModel.hpp"

namespace collision {

class PairModel : public InteractionModel {
 public:
  using InteractionModel::InteractionModel;

  /// the names New() builds
  static const std::vector<std::string>& names();

  /// @throws std::invalid_argument on an unknown name (listing names()) or invalid parameters
  static std::unique_ptr<PairModel> New(const std::string& name,
                                        const InteractionParameters& parameters);
};

}  // namespace collision

#endif
