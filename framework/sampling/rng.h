// A small, fast, seedable random number generator with independent streams.
#pragma once

#include <cstdint>

#include <glm/vec2.hpp>

namespace pt {

/// PCG32 (O'Neill 2014, pcg-random.org): 64-bit state, 32-bit output, and a stream selector, so
/// every pixel gets its own sequence from (seed, pixel index) and an image does not depend on
/// which thread rendered which tile.
class Rng {
 public:
  explicit Rng(uint64_t seed = 0x853c49e6748fea9bULL, uint64_t stream = 0xda3e39cb94b95bdbULL) {
    state_ = 0u;
    inc_ = (stream << 1u) | 1u;
    next_u32();
    state_ += seed;
    next_u32();
  }

  uint32_t next_u32() {
    uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + inc_;
    uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31));
  }

  /// Uniform in [0, 1): the top 24 bits, so the result is exactly representable and never 1.
  float next_float() { return float(next_u32() >> 8) * 0x1p-24f; }
  glm::vec2 next_2d() {
    float a = next_float();
    return {a, next_float()};
  }

 private:
  uint64_t state_, inc_;
};

}  // namespace pt
