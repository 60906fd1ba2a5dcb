/**
 * @file BodySet.hpp
 * @brief What the collision sub-step (SubStepper) needs of the bodies it
 *        moves: how the collision model sees each one, and how each one
 *        moves under a collision force and its own other forces.
 *
 * Implemented in vacuum by RigidBodySet (tests, validation/dryCollisions) and
 * in a flow by the OpenFOAM library's coupledBodySet (hydrodynamic force,
 * buoyant weight, virtual mass, the body's motion model): both step through
 * the same SubStepper.
 */
#ifndef COLLISION_BODYSET_HPP
#define COLLISION_BODYSET_HPP

#include "collision/CollisionModel.hpp"
#include "collision/RigidBodyStep.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace collision {

class BodySet {
 public:
  virtual ~BodySet() = default;

  virtual std::size_t size() const = 0;

  /// Body i's name for messages.
  virtual std::string name(std::size_t i) const { return "body " + std::to_string(i); }

  /// Body i at the state s as the collision model sees it.
  virtual CollisionBody collisionBody(std::size_t i, const BodyState& s) const = 0;

  /// Every body at its state (one state per body).
  std::vector<CollisionBody> collisionBodies(const std::vector<BodyState>& states) const {
    std::vector<CollisionBody> bodies;
    bodies.reserve(states.size());
    for (std::size_t i = 0; i < states.size(); ++i) bodies.push_back(collisionBody(i, states[i]));
    return bodies;
  }

  /**
   * Advance s, a state of body i, from t over dt under the collision force
   * fc and torque tc (about the centre, held over the step) and the body's
   * other forces. Called for trial states too: it must not change the set.
   */
  virtual void advance(std::size_t i, BodyState& s, Scalar t, Scalar dt, const Vec3& fc,
                       const Vec3& tc) const = 0;

  /// Body i took the step from start to end under fc, tc (e.g. to keep its
  /// accelerations); with a work share called on the process that owns body i.
  virtual void accept(std::size_t /*i*/, const BodyState& /*start*/, const BodyState& /*end*/,
                      Scalar /*dt*/, const Vec3& /*fc*/, const Vec3& /*tc*/) {}
};

}  // namespace collision

#endif
