// Types the studio passes between its GUI thread and its solver thread, registered with Qt.
#pragma once

#include "solver/scene/Plan.h"
#include "solver/scene/Snapshot.h"

#include <QMetaType>

namespace lbdem::studio {

/// What the worker is doing, as the toolbar and status line show it.
enum class RunState { Empty, Ready, Running, Paused, Finished, Failed };

/// Throughput figures of the running simulation, sent a few times a second.
struct RunProgress {
    long long step = 0;          ///< steps taken since the start
    double time_over_tc = 0;     ///< t / tau_c
    double end_time_over_tc = 0; ///< t / tau_c at which the case ends
    double steps_per_second = 0; ///< over the last reporting interval
    double mlups = 0;            ///< million lattice-node updates per second (0 when dry)
    double eta_seconds = -1;     ///< wall time left at the current pace; < 0 while unknown
    int threads = 0;             ///< OpenMP team size of the solver thread (0: not measured)
};

/// Register the types above and the snapshot pointer for queued connections; call once
/// before any SimulationController is made (idempotent).
void registerStudioTypes();

/// Word for a run state, as shown in the status line ("running", "paused", ...).
const char* runStateName(RunState state);

} // namespace lbdem::studio

Q_DECLARE_METATYPE(lbdem::solver::SnapshotPtr)
Q_DECLARE_METATYPE(lbdem::solver::Plan)
Q_DECLARE_METATYPE(lbdem::studio::RunState)
Q_DECLARE_METATYPE(lbdem::studio::RunProgress)
