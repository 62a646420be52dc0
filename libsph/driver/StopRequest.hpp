// SIGINT and SIGTERM ask a running case to stop as OpenFOAM's `stopAt writeNow` does: the
// current step finishes, the state is written, and the solver exits cleanly. A second signal
// terminates at once (the default action is restored by the first).
#pragma once

namespace sph {

class StopRequest {
public:
    StopRequest();   // installs the handlers
    ~StopRequest();  // restores the previous handlers
    StopRequest(const StopRequest&) = delete;
    StopRequest& operator=(const StopRequest&) = delete;

    // The signal received since construction, 0 if none.
    int signal() const;
};

// "SIGINT", "SIGTERM", or the number.
const char* signalName(int signal);

}  // namespace sph
