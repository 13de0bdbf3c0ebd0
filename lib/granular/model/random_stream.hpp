#pragma once
// Reproducible uniform random numbers: realization r of seed s is a pure function of (s, r),
// whatever the thread, process or order it runs in (SPEC §2). Philox4x64-10 from Random123,
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
    return static_cast<double>(block_[used_++] >> 11) * 0x1.0p-53;
  }

 private:
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
