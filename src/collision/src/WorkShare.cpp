#include "collision/WorkShare.hpp"

namespace collision {

int WorkShare::owner(std::uint64_t key) const {
  // splitmix64's finaliser: neighbouring keys (a body's pairs) land on
  // unrelated processes
  std::uint64_t z = key + 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return static_cast<int>(z % static_cast<std::uint64_t>(size()));
}

}  // namespace collision
