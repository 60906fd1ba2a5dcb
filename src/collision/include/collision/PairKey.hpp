/**
 * @file PairKey.hpp
 * @brief The 64-bit key of a pair in CollisionModel's histories: the first
 *        body, the image of the second (PeriodicBox image code) and the second
 *        (a body index, or -1 - wall index for a wall).
 *
 * Bits: first (25: up to kMaxBodies bodies), image (7), second (32).
 */
#ifndef COLLISION_PAIRKEY_HPP
#define COLLISION_PAIRKEY_HPP

#include "collision/PeriodicBox.hpp"

#include <cstdint>

namespace collision {

struct PairKey {
  static constexpr int kMaxBodies = 1 << 25;
  static_assert(PeriodicBox::kImageCodes <= 128, "an image code must fit in 7 bits");

  static std::uint64_t encode(int first, int second, int image = PeriodicBox::kNoImage) {
    return (std::uint64_t(std::uint32_t(first)) << 39) | (std::uint64_t(std::uint32_t(image)) << 32) |
           std::uint32_t(second);
  }
  static int first(std::uint64_t k) { return static_cast<int>(k >> 39); }
  static int image(std::uint64_t k) { return static_cast<int>((k >> 32) & 0x7fu); }
  static int second(std::uint64_t k) { return static_cast<int>(static_cast<std::uint32_t>(k & 0xffffffffu)); }
};

}  // namespace collision

#endif
