// Counter-based random streams (Philox4x64-10, Random123; Salmon et al.,
// "Parallel random numbers: as easy as 1, 2, 3", SC'11).
//
// A stream is addressed, not advanced by a shared state: its key is
// {experiment seed, trial index} and its counter is {decision index, purpose,
// block}. A draw therefore depends only on where it is asked for, never on how
// many other draws were made before, by which thread, or in which order: the
// basis of vahf's bit-for-bit reproducibility (docs/design.md, decision 9). There is
// no global random state anywhere in vahf.
#pragma once

#include <array>
#include <cstdint>

namespace vahf::rng {

// What a draw is for. Each purpose has its own counter lane, so adding draws
// for one purpose never shifts another's. Values are part of the file format
// of every seeded result: never renumber, only append.
enum class Purpose : std::uint32_t {
  kTargetEstimate = 1,  // c1, c2, c3 of Eq. 5
  kVisionError = 2,     // E_i of Eq. 5
  kTorqueError = 3,     // perturbation of the assembly torque
  kOperatorVariation = 4,
  kMeasurementNoise = 5,  // a synthetic lab's reading errors (calibrate/synthetic_lab.h)
  kTest = 0xFFFF,         // reserved for tests
};

struct StreamKey {
  std::uint64_t seed = 0;   // the experiment seed
  std::uint64_t trial = 0;  // the trial index within the experiment
};

// One stream of draws at {key, decision, purpose}. Successive calls walk the
// block counter; two Stream objects with the same address give the same bits.
class Stream {
 public:
  Stream(StreamKey key, std::uint64_t decision, Purpose purpose);

  // 64 raw bits.
  std::uint64_t Bits();
  // Uniform on (0, 1] (Random123 u01: never 0, so log() is safe).
  double Uniform();
  // Standard normal by the Box-Muller transform of Random123's boxmuller.hpp.
  double Normal();

 private:
  void Refill();

  std::array<std::uint64_t, 2> key_;
  std::array<std::uint64_t, 4> counter_;
  std::array<std::uint64_t, 4> block_{};
  int used_ = 4;  // words of block_ already handed out
  bool has_spare_normal_ = false;
  double spare_normal_ = 0.0;
};

}  // namespace vahf::rng
