#pragma once
// Reproducible uniform random numbers: realization r of seed s is a pure function of (s, r),
// whatever the thread, process or order it runs in (docs/physics.md, "Disorder"). Philox4x64-10 from Random123,
// keyed by (seed, realization), counting up from 0.
#include <array>
#include <cstdint>

#include <Random123/philox.h>

namespace granular {

class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::uint64_t realization) : key_{{seed, realization}} {}

  /// Uniform on [0, 1), 53 random bits.
  double uniform() {
    if (used_ == 4) refill();
    return to_unit(block_[used_++]);
  }

  /// Uniforms number 4b … 4b+3 of the stream (0-based): what calls 4b+1 … 4b+4 of uniform()
  /// return, computed directly (the generator is counter-based), so a long chain can be drawn
  /// in any order, a piece at a time, without storing it.
  std::array<double, 4> uniform_block(std::uint64_t b) const {
    const r123::Philox4x64::ctr_type counter{{b, 0, 0, 0}};
    const auto bits = r123::Philox4x64()(counter, key_);
    return {to_unit(bits[0]), to_unit(bits[1]), to_unit(bits[2]), to_unit(bits[3])};
  }

 private:
  static double to_unit(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }
  void refill() {
    const r123::Philox4x64::ctr_type counter{{counter_++, 0, 0, 0}};
    block_ = generator_(counter, key_);
    used_ = 0;
  }
  r123::Philox4x64 generator_;
  r123::Philox4x64::key_type key_;
  r123::Philox4x64::ctr_type block_{};
  std::uint64_t counter_ = 0;
  int used_ = 4;
};

}  // namespace granular
