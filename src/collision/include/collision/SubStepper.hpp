/**
 * @file SubStepper.hpp
 * @brief One body sub-step with collisions: the scheme of every coupled run,
 *        of the collision unit tests and of validation/dryCollisions.
 *
 * Heun's predictor-corrector on the collision force, then the implicit
 * damping (CollisionModel::dampingForces):
 *  1. the collision forces at the start states (recording the damped pairs);
 *  2. the states advanced under them and every other force (predictor), the
 *     collision forces there; the collision force of the sub-step is the
 *     mean of the two;
 *  3. if pairs were recorded: the end velocities under that mean and every
 *     other force, and the damping forces implicit in them, added to it;
 *  4. each body advanced from its start state under the sum.
 * Without a collision model the bodies are advanced under their other forces.
 * validation/dryCollisions measures the scheme's restitution error against
 * subStepsPerContact.
 */
#ifndef COLLISION_SUBSTEPPER_HPP
#define COLLISION_SUBSTEPPER_HPP

#include "collision/BodySet.hpp"

#include <vector>

namespace collision {

class SubStepper {
 public:
  /**
   * Advance states (one per body of bodies) from t over dt.
   * @param model the collision model, or nullptr for none
   * @param contactTime the nominal contact time T_c (CollisionModel::forces)
   * @param referenceStates the bodies' states whose velocities the flow's
   *        hydrodynamic force responded to (the film correction; may be
   *        empty when no body has a film gap)
   * @throws std::invalid_argument if states has another size than bodies
   */
  void step(BodySet& bodies, std::vector<BodyState>& states, CollisionModel* model,
            Scalar contactTime, Scalar t, Scalar dt,
            const std::vector<BodyState>& referenceStates = {});

  /// The collision force and torque (about the centre) each body got in the last step.
  const std::vector<Vec3>& force() const { return force_; }
  const std::vector<Vec3>& torque() const { return torque_; }

 private:
  std::vector<CollisionBody> start_, predicted_;
  std::vector<BodyState> trial_;
  std::vector<Vec3> force_, torque_, force1_, torque1_, endVelocity_, endAngularVelocity_,
      referenceVelocity_, referenceAngularVelocity_;
};

}  // namespace collision

#endif
