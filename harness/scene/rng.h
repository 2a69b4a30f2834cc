// Seeded random numbers for the scene generator. Everything random in a scene (texture, sensor
// noise, encoder slip and noise) comes from here, keyed by (seed, frame, purpose), so a frame's
// bytes depend only on the spec and its index, never on the order frames are produced in.
// std::normal_distribution is avoided because its algorithm differs between C++ libraries.
#pragma once

#include <cmath>
#include <cstdint>

namespace bvb {

inline uint64_t mix64(uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}
inline uint64_t hash_key(uint64_t a, uint64_t b, uint64_t c = 0, uint64_t d = 0) {
  return mix64(mix64(mix64(mix64(a) ^ b) ^ c) ^ d);
}

// splitmix64 stream. Not the checks' Rng (harness/lib/check.h): the scenes' frames, and with
// them the bundled scenes and every number measured on them, depend on this exact sequence.
struct SceneRng {
  uint64_t state;
  explicit SceneRng(uint64_t seed) : state(seed) {}
  uint64_t next() { return mix64(state += 0x9e3779b97f4a7c15ull); }
  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }
  // Standard normal (Box-Muller, both values used).
  double gaussian() {
    if (has_spare) {
      has_spare = false;
      return spare;
    }
    double u1 = uniform(), u2 = uniform();
    if (u1 < 1e-300) u1 = 1e-300;
    const double r = std::sqrt(-2.0 * std::log(u1)), a = 6.283185307179586 * u2;
    spare = r * std::sin(a);
    has_spare = true;
    return r * std::cos(a);
  }

 private:
  bool has_spare = false;
  double spare = 0;
};

}  // namespace bvb
