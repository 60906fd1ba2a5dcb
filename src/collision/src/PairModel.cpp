#include "collision/PairModel.hpp"

#include "collision/NoLubrication.hpp"
#include "collision/StokesLubrication.hpp"

#include <stdexcept>

namespace collision {

const std::vector<std::string>& PairModel::names() {
  static const std::vector<std::string> names{"springDashpot", "lubricatedSpringDashpot"};
  return names;
}

std::unique_ptr<PairModel> PairModel::New(const std::string& name,
                                          const InteractionParameters& parameters) {
  parameters.validate();
  const SpringDashpotContact contact(parameters.contact.restitution,
                                     parameters.contact.sustainedLoadOverlap);
  std::unique_ptr<Friction> friction = makeFriction(parameters.contact);
  if (name == "springDashpot") {
    return std::make_unique<PairModel>(name, contact, std::move(friction),
                                       std::make_unique<NoLubrication>(), parameters.contact.rollingFriction);
  }
  if (name == "lubricatedSpringDashpot") {
    return std::make_unique<PairModel>(
        name, contact, std::move(friction),
        std::make_unique<StokesLubrication>(parameters.viscosity, parameters.lubrication, false),
        parameters.contact.rollingFriction);
  }
  throw std::invalid_argument("collision: unknown pair model '" + name +
                              "' (allowed: " + list(names()) + ")");
}

}  // namespace collision
