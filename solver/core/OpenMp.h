// Thin wrappers so that the kernels build with and without OpenMP.
#pragma once

#ifdef _OPENMP
#include <omp.h>
#endif

namespace lbdem::solver {

/// Threads an OpenMP parallel region would use by default (1 without OpenMP).
inline int ompMaxThreads() {
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}

/// Threads in the current parallel region (1 outside one, or without OpenMP).
inline int ompThreadCount() {
#ifdef _OPENMP
    return omp_get_num_threads();
#else
    return 1;
#endif
}

/// Use this many threads in the following parallel regions (n <= 0: leave the default).
inline void ompSetThreads(int n) {
#ifdef _OPENMP
    if (n > 0) omp_set_num_threads(n);
#else
    (void)n;
#endif
}

/// Processors OpenMP may use (1 without OpenMP).
inline int ompProcessorCount() {
#ifdef _OPENMP
    return omp_get_num_procs();
#else
    return 1;
#endif
}

/// The size of the team a parallel region gets now: measured in one, so that a thread limit or
/// dynamic adjustment shows (1 without OpenMP).
inline int ompTeamSize() {
    int team = 1;
#ifdef _OPENMP
#pragma omp parallel
    {
#pragma omp single
        team = omp_get_num_threads();
    }
#endif
    return team;
}

/// Index of the calling thread in the current parallel region (0 without OpenMP).
inline int ompThreadIndex() {
#ifdef _OPENMP
    return omp_get_thread_num();
#else
    return 0;
#endif
}

} // namespace lbdem::solver
