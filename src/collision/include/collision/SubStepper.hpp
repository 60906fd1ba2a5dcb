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
 * stepIslands() takes a fluid step island by island (CollisionModel::islands):
 * the islands that need the same number of sub-steps step together, so that
 * a body far from any other takes the fewest and a contact's island the
 * sub-steps its contact needs. With a work share, each process builds the
 * trial states of the bodies its own pairs use (evaluatedBodies()) and of
 * the damped pairs' bodies; the collision forces of every body reach every
 * process through the model's collectives; each process advances the bodies
 * it owns to the end of the sub-step and one collective per sub-step gives
 * every process every body's end state; with damped pairs, one more gives
 * every process what the damping solve needs of their bodies, each from
 * its owner.
 * validation/dryCollisions measures the scheme's restitution error against
 * subStepsPerContact.
 */
#ifndef COLLISION_SUBSTEPPER_HPP
#define COLLISION_SUBSTEPPER_HPP

#include "collision/BodySet.hpp"
#include "collision/CollisionModel.hpp"

#include <functional>
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
   * @param active the bodies that take the sub-step (nullptr: all)
   * @param evaluated with a work share, the model's evaluatedBodies(): the
   *        trial states are built for these only (and for the bodies of the
   *        damped pairs)
   * @param advanced the active bodies whose end states this process computes
   *        (nullptr: all; with a work share, those it owns: the caller
   *        gathers the others')
   * @throws std::invalid_argument if states has another size than bodies
   */
  void step(BodySet& bodies, std::vector<BodyState>& states, CollisionModel* model,
            Scalar contactTime, Scalar t, Scalar dt,
            const std::vector<BodyState>& referenceStates = {},
            const std::vector<char>* active = nullptr,
            const std::vector<char>* evaluated = nullptr,
            const std::vector<char>* advanced = nullptr);

  /**
   * Advance states from t over the fluid step dt island by island: each
   * island in max(minSubSteps, its sub-steps) sub-steps (the islands with
   * the same number together; those that do not interact without collision
   * forces), then CollisionModel::checkIslands. meanForce(), meanTorque():
   * each body's collision force and torque over the step; subSteps(): each
   * body's number of sub-steps.
   * @throws TooManySubSteps, and what step() and checkIslands() throw
   */
  void stepIslands(BodySet& bodies, std::vector<BodyState>& states, CollisionModel& model,
                   Scalar contactTime, Scalar t, Scalar dt, int minSubSteps,
                   const std::vector<BodyState>& referenceStates = {});

  /// The collision force and torque (about the centre) each body got in the last step.
  const std::vector<Vec3>& force() const { return force_; }
  const std::vector<Vec3>& torque() const { return torque_; }

  /// stepIslands(): each body's mean collision force and torque over the fluid step
  const std::vector<Vec3>& meanForce() const { return meanForce_; }
  const std::vector<Vec3>& meanTorque() const { return meanTorque_; }
  /// stepIslands(): each body's sub-steps, and the islands of the step
  const std::vector<int>& subSteps() const { return bodySubSteps_; }
  const std::vector<Island>& islands() const { return islands_; }

 private:
  std::vector<CollisionBody> start_, predicted_;
  std::vector<BodyState> trial_;
  std::vector<Vec3> force_, torque_, force1_, torque1_, endVelocity_, endAngularVelocity_,
      referenceVelocity_, referenceAngularVelocity_, meanForce_, meanTorque_;
  std::vector<int> bodySubSteps_;
  std::vector<Island> islands_;
  std::vector<char> active_;
  std::vector<char> damped_;  ///< step(): the bodies of the damped pairs
  std::vector<char> owned_;   ///< stepIslands() with a work share: this process's bodies

  /// every process's owned active bodies' end states to every process (one collective)
  void gatherStates(const WorkShare& share, std::vector<BodyState>& states);
  /// what the damping solve needs of the damped pairs' bodies (end velocities,
  /// mass, inverse inertia, mobility) from their owners (advanced) to every
  /// process (one collective)
  void gatherDampedBodies(const WorkShare& share, const std::vector<char>& advanced,
                          const std::function<bool(std::size_t)>& on);
};

}  // namespace collision

#endif
