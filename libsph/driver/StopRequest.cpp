#include "driver/StopRequest.hpp"

#include <csignal>

namespace sph {

namespace {

volatile std::sig_atomic_t received = 0;
struct sigaction previousInterrupt, previousTerminate;

extern "C" void requestStop(int signal) {
    received = signal;
    // The next signal of either kind takes its default action: a user who presses Ctrl-C twice
    // does not wait for the step to finish.
    struct sigaction defaults {};
    defaults.sa_handler = SIG_DFL;
    sigaction(SIGINT, &defaults, nullptr);
    sigaction(SIGTERM, &defaults, nullptr);
}

}  // namespace

StopRequest::StopRequest() {
    received = 0;
    struct sigaction action {};
    action.sa_handler = requestStop;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previousInterrupt);
    sigaction(SIGTERM, &action, &previousTerminate);
}

StopRequest::~StopRequest() {
    sigaction(SIGINT, &previousInterrupt, nullptr);
    sigaction(SIGTERM, &previousTerminate, nullptr);
}

int StopRequest::signal() const { return received; }

const char* signalName(int signal) {
    switch (signal) {
        case SIGINT: return "SIGINT";
        case SIGTERM: return "SIGTERM";
        default: return "a signal";
    }
}

}  // namespace sph
