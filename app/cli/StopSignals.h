// SIGINT and SIGTERM during a run: finish the step, checkpoint, and say how to continue.
#pragma once

#include <stdexcept>
#include <string>

namespace lbdem::cli {

/// While alive, SIGINT and SIGTERM only ask the run to stop (stopSignal() says which came); a
/// second one of either ends the process at once, as the signal would have. The handlers that
/// were in place come back when it is destroyed.
class StopSignals {
public:
    StopSignals();
    ~StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

    /// The signal that asked the run to stop, or 0 while none has.
    static int stopSignal();
};

/// Thrown by a run stopped by a signal after it wrote its checkpoint; the CLI prints what() and
/// exits with exitCode() (128 + the signal, as a shell reports a process the signal ended).
class StoppedBySignal : public std::runtime_error {
public:
    StoppedBySignal(int signal, const std::string& message);
    int exitCode() const { return 128 + m_signal; }

private:
    int m_signal;
};

} // namespace lbdem::cli
