#pragma once
// Counter-based random numbers: every value is a pure function of (seed, stream, index,
// dimension), so a pixel's samples do not depend on which thread, tile or machine made them.
#include <array>
#include <bit>
#include <cstdint>

namespace landsim {

// SplitMix64 finaliser: a bijective 64-bit mixer with full avalanche.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

constexpr std::uint64_t hash_combine(std::uint64_t h, std::uint64_t v) {
  return mix64(h ^ mix64(v));
}

constexpr std::uint32_t reverse_bits(std::uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

// The Laine-Karras permutation (2011, as Burley 2020 "Practical hash-based Owen scrambling"
// gives it): each bit flipped by a hash of the bits below it, seeded. On bit-reversed values
// it is an Owen scramble: each bit flipped by a hash of the bits above it.
constexpr std::uint32_t laine_karras(std::uint32_t x, std::uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

// The first two dimensions of the Sobol sequence, a (0, 2)-sequence: every 2^k consecutive
// points from 0 put one point in each of any 2^k elementary intervals of the unit square.
// Kept bit-reversed (the first dimension is then the index itself, van der Corput's), so that
// the Owen scramble needs one reversal: the second dimension's generator matrix columns
// (v_0 = 2^31, v_j = v_{j-1} xor v_{j-1} >> 1), reversed.
struct SobolColumns {
  std::uint32_t v[32];
  constexpr SobolColumns() : v{} {
    std::uint32_t c = 1u << 31;
    for (int j = 0; j < 32; ++j, c ^= c >> 1) v[j] = reverse_bits(c);
  }
};
inline constexpr SobolColumns kSobolColumns{};

constexpr std::uint32_t reversed_sobol(std::uint32_t index, std::uint32_t component) {
  if (component == 0) return index;
  std::uint32_t r = 0;
  for (; index != 0; index &= index - 1) r ^= kSobolColumns.v[std::countr_zero(index)];
  return r;
}

// An Owen-scrambled Sobol coordinate in [0, 2^32).
constexpr std::uint32_t scrambled_sobol(std::uint32_t index, std::uint32_t component,
                                        std::uint32_t seed) {
  return reverse_bits(laine_karras(reversed_sobol(index, component), seed));
}

// How a pixel's samples draw their numbers: independent (each a hash), or padded
// Owen-scrambled Sobol (each pair of dimensions a (0, 2)-sequence over the pixel's sample
// indices, scrambled per pixel and pair: stratified in every pair, pbrt-v4's PaddedSobol).
enum class SampleSequence { independent, sobol };

class CounterRng {
 public:
  // One stream per (seed, key): key is, for a renderer, the pixel index; index the sample.
  constexpr CounterRng(std::uint64_t seed, std::uint64_t key, std::uint64_t index,
                       SampleSequence sequence = SampleSequence::independent)
      : stream_(hash_combine(mix64(seed), key)),
        base_(hash_combine(stream_, index)),
        index_(static_cast<std::uint32_t>(index)),
        sobol_(sequence == SampleSequence::sobol) {}

  // The value for one dimension of the sample, uniform in [0, 1).
  constexpr float uniform(std::uint32_t dimension) const {
    if (sobol_) {
      // Each pair of dimensions takes the pixel's samples in its own order, so that pairs are
      // not correlated with one another: the index Owen-scrambled (Burley's shuffle; an
      // aligned block of 2^k indices stays one, so a power-of-two sample count keeps the pair
      // stratified; a xor would not do: under the scramble below every pair would see the
      // same points). One hash per pair: its low half orders the samples (the pair's two
      // dimensions must take the same order), its high half seeds each dimension's scramble.
      const std::uint64_t pair = hash_combine(stream_, dimension >> 1);
      return sobol_component(pair, shuffled_index(pair), dimension & 1u);
    }
    const std::uint64_t bits = hash_combine(base_, dimension);
    return unit(static_cast<std::uint32_t>(bits >> 32));
  }

  // The values of dimensions `first` and first + 1 (first even: a Sobol pair), equal to
  // {uniform(first), uniform(first + 1)}; under Sobol the pair's hash and its shuffled index
  // are computed once for both.
  constexpr std::array<float, 2> uniform2(std::uint32_t first) const {
    if (!sobol_ || (first & 1u) != 0) return {uniform(first), uniform(first + 1)};
    const std::uint64_t pair = hash_combine(stream_, first >> 1);
    const std::uint32_t index = shuffled_index(pair);
    return {sobol_component(pair, index, 0), sobol_component(pair, index, 1)};
  }

  // Next dimension, for code that consumes dimensions in order.
  float next() { return uniform(dimension_++); }

 private:
  // The sample's index in the pair's own order (the pair hash's low half seeds it).
  constexpr std::uint32_t shuffled_index(std::uint64_t pair) const {
    return reverse_bits(laine_karras(reverse_bits(index_), static_cast<std::uint32_t>(pair)));
  }

  // One component of the pair's scrambled point; the hash's high half seeds each component's
  // scramble, the second's offset so the two differ.
  static constexpr float sobol_component(std::uint64_t pair, std::uint32_t index,
                                         std::uint32_t component) {
    const std::uint32_t seed = static_cast<std::uint32_t>(pair >> 32) ^ (component * 0x9e3779b9u);
    return unit(scrambled_sobol(index, component, seed));
  }

  // The top 24 bits as a float in [0, 1).
  static constexpr float unit(std::uint32_t bits) {
    return static_cast<float>(bits >> 8) * (1.0f / 16777216.0f);
  }

  std::uint64_t stream_;  // the pixel's (Sobol: the scrambles' seed); declared first: base_
                          // is made from it
  std::uint64_t base_;
  std::uint32_t index_;  // the sample (Sobol: its index in the sequence)
  bool sobol_;
  std::uint32_t dimension_ = 0;
};

}  // namespace landsim
