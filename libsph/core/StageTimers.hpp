// Wall time spent per part of a run, so the log can say where the time goes.
#pragma once

#include <array>
#include <chrono>
#include <string_view>

namespace sph {

enum class Stage { Neighbours, Density, Boundary, Forces, Integrator, Shifting, FunctionObjects, Output, Count };

inline constexpr std::array<std::string_view, static_cast<std::size_t>(Stage::Count)> stageNames{
    "neighbour search", "density + pressure", "boundary models", "forces", "integrator", "particle shifting", "function objects", "output"};

class StageTimers {
public:
    class Scope {
    public:
        Scope(StageTimers& timers, Stage stage) : timers_(timers), stage_(stage), start_(std::chrono::steady_clock::now()) {}
        ~Scope() {
            timers_.seconds_[static_cast<std::size_t>(stage_)] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        }
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        StageTimers& timers_;
        Stage stage_;
        std::chrono::steady_clock::time_point start_;
    };

    Scope time(Stage stage) { return Scope(*this, stage); }
    double seconds(Stage stage) const { return seconds_[static_cast<std::size_t>(stage)]; }

private:
    std::array<double, static_cast<std::size_t>(Stage::Count)> seconds_{};
};

}  // namespace sph
