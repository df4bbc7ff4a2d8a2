// Subnormal numbers read and written as zero by the calling thread, for the float lattice kernels.
//
// Float storage holds the deviations f_i - w_i, which in still fluid (ahead of a sound front, in
// the absorbing layer) and in the Smagorinsky model's squared stresses fall below float's least
// normal number, 1.2e-38. Every operation on such a subnormal number takes a microcode assist of
// about a hundred cycles on x86: the paper case's float stream-collide took 5.5 ms per step
// instead of 2.5 (docs/performance.md, "Subnormal floats"). A value that small is 30 orders of
// magnitude below float's resolution of a population (about 3e-8 of w_i), so reading and writing
// it as zero changes nothing that float storage can represent. Double storage never gets there
// (its least normal number is 2.2e-308) and does not use this.
#pragma once

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#define LBDEM_HAS_MXCSR 1
#endif

namespace lbdem::solver {

/// While alive and enabled, the calling thread's vector arithmetic flushes subnormal results to
/// zero and reads subnormal inputs as zero (MXCSR FTZ and DAZ); the previous mode comes back after.
/// Per thread: construct it inside each parallel region. Does nothing where there is no MXCSR.
class ScopedFlushSubnormals {
public:
    explicit ScopedFlushSubnormals(bool enabled) {
#ifdef LBDEM_HAS_MXCSR
        if (!enabled) return;
        m_saved = _mm_getcsr();
        m_active = true;
        _mm_setcsr(m_saved | kFlushToZero | kDenormalsAreZero);
#else
        (void)enabled;
#endif
    }
    ~ScopedFlushSubnormals() {
#ifdef LBDEM_HAS_MXCSR
        if (m_active) _mm_setcsr(m_saved);
#endif
    }
    ScopedFlushSubnormals(const ScopedFlushSubnormals&) = delete;
    ScopedFlushSubnormals& operator=(const ScopedFlushSubnormals&) = delete;

private:
    static constexpr unsigned kFlushToZero = 0x8000, kDenormalsAreZero = 0x0040;
    unsigned m_saved = 0;
    bool m_active = false;
};

} // namespace lbdem::solver
