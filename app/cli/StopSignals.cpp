// Signal handlers that turn the first SIGINT or SIGTERM into a request to stop the run.
#include "app/cli/StopSignals.h"

#include <csignal>

namespace lbdem::cli {

namespace {

volatile std::sig_atomic_t g_stopSignal = 0;
struct sigaction g_previousInt, g_previousTerm;

extern "C" void requestStop(int signal) {
    if (g_stopSignal != 0) {
        // A second signal: the user does not want to wait for the step and the checkpoint.
        std::signal(signal, SIG_DFL);
        std::raise(signal);
        return;
    }
    g_stopSignal = signal;
}

/// Install action for signal unless the signal is ignored (a background job of a shell script
/// ignores SIGINT, and must go on ignoring it); previous receives the old disposition.
void install(int signal, const struct sigaction& action, struct sigaction& previous) {
    sigaction(signal, nullptr, &previous);
    if (previous.sa_handler != SIG_IGN) sigaction(signal, &action, nullptr);
}

} // namespace

StopSignals::StopSignals() {
    g_stopSignal = 0;
    struct sigaction action {};
    action.sa_handler = requestStop;
    // Neither handler interrupts the other: of two signals, the second always sees the first.
    sigemptyset(&action.sa_mask);
    sigaddset(&action.sa_mask, SIGINT);
    sigaddset(&action.sa_mask, SIGTERM);
    action.sa_flags = SA_RESTART; // file writes in progress go on instead of failing with EINTR
    install(SIGINT, action, g_previousInt);
    install(SIGTERM, action, g_previousTerm);
}

StopSignals::~StopSignals() {
    sigaction(SIGINT, &g_previousInt, nullptr);
    sigaction(SIGTERM, &g_previousTerm, nullptr);
}

int StopSignals::stopSignal() {
    return g_stopSignal;
}

StoppedBySignal::StoppedBySignal(int signal, const std::string& message)
    : std::runtime_error(message), m_signal(signal) {}

} // namespace lbdem::cli
