// SPDX-License-Identifier: BSL-1.0
// pointmass/denormals.hpp — subnormal numbers flushed to zero while a guard lives.
//
// Damping takes every velocity component that nothing feeds (x and z under gravity, all three
// for particles at rest) towards zero geometrically, and after enough steps into the
// subnormal range: below 1.2e-38 in float, where at damping 0.9 per second and 60 steps a
// second a velocity of 10 m/s arrives after about 14 minutes (in double, below 2.2e-308,
// after about 2 hours). There it decays to a few hundred times the smallest subnormal and
// stays (the damped value rounds back to itself), and on many x86 processors every operation
// on a subnormal takes a microcode assist: the step of a system whose particles have come to
// rest becomes tens of times slower (docs/results/subnormal.md measures it).
// The values involved are far below anything a game can see, and treating them as zero is
// what the processor's flush-to-zero (FTZ) and denormals-are-zero (DAZ) modes do.
//
// FlushDenormals sets both modes for the calling thread while it lives and restores the
// previous modes when it is destroyed, the way game physics engines guard their update. Put
// one around the frame's simulation, or around the thread's whole loop:
//
//   {
//     pointmass::FlushDenormals flush;  // this thread, to the end of the block
//     sparks.step(dt);
//   }
//
// Results change only where a value would have been subnormal: such a result, or operand,
// is zero instead (a Particle and a ParticleSystem stepped under the same modes still agree
// bit for bit). The step never sets the modes itself: a step that switched them would make a
// ParticleSystem and a Particle stepped by the same caller disagree wherever a value is
// subnormal, and every bit-for-bit result (Cyclone's trajectories, the determinism digests)
// would hold for normal numbers only. The modes belong to a thread: each worker of a thread
// pool of the caller's needs a guard of its own. pointmass::step on a standard execution
// policy (parallel.hpp) needs none: it runs every chunk under the modes of the thread that
// called it (and gives each worker its own back after), so a guard around the call covers its
// workers, whatever modes the pool's threads had. Supported with g++ and clang
// on x86-64 and on 32-bit x86 with SSE (the MXCSR register's FTZ and DAZ bits), on 64-bit
// ARM (the FPCR register's FZ bit, which flushes subnormal operands and results alike) and on
// 32-bit ARM with a floating-point unit (the FPSCR's FZ bit, the same); elsewhere `supported`
// is false and the guard does nothing.
//
// Owns: FlushDenormals, and detail::SameFlushModes (a chunk of a parallel step under the
// calling thread's modes).
// Must not include: anything but config.hpp.
#pragma once

#include "config.hpp"

// Which register holds the modes: 1, x86's MXCSR; 2, AArch64's FPCR; 3, 32-bit ARM's FPSCR;
// 0, none known.
#if (defined(__GNUC__) || defined(__clang__)) && \
    (defined(__x86_64__) || (defined(__i386__) && defined(__SSE__)))
#define POINTMASS_DETAIL_FLUSH_REGISTER 1
#elif (defined(__GNUC__) || defined(__clang__)) && defined(__aarch64__)
#define POINTMASS_DETAIL_FLUSH_REGISTER 2
#elif (defined(__GNUC__) || defined(__clang__)) && defined(__arm__) && defined(__ARM_FP)
#define POINTMASS_DETAIL_FLUSH_REGISTER 3
#else
#define POINTMASS_DETAIL_FLUSH_REGISTER 0
#endif

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

namespace detail {

/// The flush modes in the floating-point control register: on x86, the SSE control register
/// (MXCSR), bit 15, flush to zero, and bit 6, denormals are zero; on ARM, bit 24 (FZ) of the
/// FPCR (AArch64) or FPSCR (32-bit), which does both for single and double precision. Where
/// none exists, reads give 0 and writes do nothing.
struct FlushModeBits {
#if POINTMASS_DETAIL_FLUSH_REGISTER == 2
  using Register = unsigned long long;  // FPCR is 64 bits wide
  static constexpr unsigned flush_bits = 1u << 24;
#elif POINTMASS_DETAIL_FLUSH_REGISTER == 3
  using Register = unsigned;
  static constexpr unsigned flush_bits = 1u << 24;
#else
  using Register = unsigned;
  static constexpr unsigned flush_bits = (1u << 15) | (1u << 6);
#endif

  static Register read() noexcept {
#if POINTMASS_DETAIL_FLUSH_REGISTER == 1
    Register csr = 0;
    __asm__ __volatile__("stmxcsr %0" : "=m"(csr));
    return csr;
#elif POINTMASS_DETAIL_FLUSH_REGISTER == 2
    Register fpcr = 0;
    __asm__ __volatile__("mrs %0, fpcr" : "=r"(fpcr));
    return fpcr;
#elif POINTMASS_DETAIL_FLUSH_REGISTER == 3
    Register fpscr = 0;
    __asm__ __volatile__("vmrs %0, fpscr" : "=r"(fpscr));
    return fpscr;
#else
    return 0;
#endif
  }
  static void write(Register value) noexcept {
    // "memory": no load or store of the guarded computation moves across the change.
#if POINTMASS_DETAIL_FLUSH_REGISTER == 1
    __asm__ __volatile__("ldmxcsr %0" : : "m"(value) : "memory");
#elif POINTMASS_DETAIL_FLUSH_REGISTER == 2
    __asm__ __volatile__("msr fpcr, %0" : : "r"(value) : "memory");
#elif POINTMASS_DETAIL_FLUSH_REGISTER == 3
    __asm__ __volatile__("vmsr fpscr, %0" : : "r"(value) : "memory");
#else
    static_cast<void>(value);
#endif
  }
  /// The calling thread's flush modes (their bits; 0 where unsupported).
  static unsigned modes() noexcept { return static_cast<unsigned>(read() & flush_bits); }
  /// Sets the calling thread's flush modes to `modes` (bits of flush_bits), keeping the rest
  /// of the register: rounding and traps (the exception flags, in MXCSR and FPSCR or in
  /// AArch64's separate FPSR, stay as they are).
  static void set_modes(unsigned modes) noexcept {
    write((read() & ~Register{flush_bits}) | modes);
  }
};

/// While it lives, the calling thread takes the two flush modes `modes` (FlushModeBits::
/// modes() of another thread) and keeps everything else of its control register; then its
/// own two come back. parallel.hpp runs every chunk of a parallel step under the modes of the
/// thread that called the step, whatever modes the worker that runs it had: a thread pool
/// need not pass them on (TBB's workers, for one, keep the modes they were given when the
/// pool first ran), and the step's results are then the serial step's on every thread.
class SameFlushModes {
 public:
  explicit SameFlushModes(unsigned modes) noexcept
      : saved_(FlushModeBits::modes()), changed_(saved_ != modes) {
    if (changed_) FlushModeBits::set_modes(modes);
  }
  ~SameFlushModes() {
    if (changed_) FlushModeBits::set_modes(saved_);
  }
  SameFlushModes(const SameFlushModes&) = delete;
  SameFlushModes& operator=(const SameFlushModes&) = delete;

 private:
  unsigned saved_;
  bool changed_;
};

}  // namespace detail

/// While it lives, the calling thread flushes subnormal results to zero and reads subnormal
/// operands as zero (see the file comment); its destructor restores the previous modes.
class FlushDenormals {
 public:
  /// True where the guard can set the modes (x86 with SSE, or ARM with a floating-point unit;
  /// g++ or clang).
  static constexpr bool supported = POINTMASS_DETAIL_FLUSH_REGISTER != 0;

  FlushDenormals() noexcept : saved_(Bits::modes()) { Bits::set_modes(Bits::flush_bits); }
  /// Restores the flush modes alone: the exception flags raised meanwhile, and any other change
  /// to the control register (rounding, traps), stay.
  ~FlushDenormals() { Bits::set_modes(saved_); }
  FlushDenormals(const FlushDenormals&) = delete;
  FlushDenormals& operator=(const FlushDenormals&) = delete;

  /// True when the calling thread flushes subnormals now (every flush mode on), whether by a
  /// guard or otherwise.
  [[nodiscard]] static bool active() noexcept {
    return supported && Bits::modes() == Bits::flush_bits;
  }

 private:
  using Bits = detail::FlushModeBits;
  unsigned saved_;  // the flush modes' bits as they were
};

}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END

#undef POINTMASS_DETAIL_FLUSH_REGISTER
