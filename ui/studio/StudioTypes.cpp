// Registration of the studio's cross-thread types with Qt's meta-type system.
#include "ui/studio/StudioTypes.h"

namespace lbdem::studio {

void registerStudioTypes() {
    qRegisterMetaType<lbdem::solver::SnapshotPtr>("lbdem::solver::SnapshotPtr");
    qRegisterMetaType<lbdem::solver::Plan>("lbdem::solver::Plan");
    qRegisterMetaType<lbdem::studio::RunState>("lbdem::studio::RunState");
    qRegisterMetaType<lbdem::studio::RunProgress>("lbdem::studio::RunProgress");
}

const char* runStateName(RunState state) {
    switch (state) {
    case RunState::Empty:
        return "no case";
    case RunState::Ready:
        return "ready";
    case RunState::Running:
        return "running";
    case RunState::Paused:
        return "paused";
    case RunState::Finished:
        return "finished";
    case RunState::Failed:
        return "stopped by an error";
    }
    return "";
}

} // namespace lbdem::studio
