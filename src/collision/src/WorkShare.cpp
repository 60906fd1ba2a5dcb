#include "collision/WorkShare.hpp"

#include "collision/PairKey.hpp"

namespace collision {

int WorkShare::bodyOwner(int i) const {
  // splitmix64's finaliser: neighbouring indices (bodies placed together)
  // land on unrelated processes
  std::uint64_t z = static_cast<std::uint64_t>(i) + 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return static_cast<int>(z % static_cast<std::uint64_t>(size()));
}

int WorkShare::owner(std::uint64_t key) const { return bodyOwner(PairKey::first(key)); }

}  // namespace collision
