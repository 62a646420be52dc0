#include "driver/CaseDirectory.hpp"

#include "io/ParticleState.hpp"

#include "io/TimeName.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <regex>

#include <cerrno>
#include <csignal>
#include <limits>
#include <sys/types.h>

#include <fmt/format.h>

namespace sph {

std::string caseName(const std::filesystem::path& caseDirectory) {
    std::filesystem::path normal = std::filesystem::absolute(caseDirectory).lexically_normal();
    if (!normal.has_filename()) normal = normal.parent_path();
    return normal.filename().string();
}

std::vector<TimeDirectory> findTimeDirectories(const std::filesystem::path& caseDirectory, std::vector<std::filesystem::path>* withoutState) {
    std::vector<TimeDirectory> times;
    std::error_code ec;
    for (const auto& item : std::filesystem::directory_iterator(caseDirectory, ec)) {
        if (!item.is_directory()) continue;
        const std::string name = item.path().filename().string();
        char* end = nullptr;
        const double t = std::strtod(name.c_str(), &end);
        if (name.empty() || end != name.c_str() + name.size() || !std::isfinite(t)) continue;
        if (!std::filesystem::exists(item.path() / "fluid.vtu") && !std::filesystem::exists(item.path() / "fluid.pvtu")) {
            if (withoutState) withoutState->push_back(item.path());
            continue;
        }
        times.push_back({t, item.path()});
    }
    std::sort(times.begin(), times.end(), [](const TimeDirectory& a, const TimeDirectory& b) { return a.time < b.time; });
    return times;
}

std::vector<std::string> stateFilesOf(const TimeDirectory& written) {
    const std::string name = written.path.filename().string();
    return {name + "/" + stateFile(written.path, "fluid").filename().string(), name + "/" + stateFile(written.path, "walls").filename().string()};
}

std::vector<TimeDirectory> timesAfter(const std::filesystem::path& caseDirectory, double time) {
    std::vector<TimeDirectory> later = findTimeDirectories(caseDirectory);
    std::erase_if(later, [&](const TimeDirectory& t) { return t.time <= time + 1e-9 * std::max(1.0, std::abs(time)); });
    return later;
}

void removeTimeDirectories(const std::vector<TimeDirectory>& times) {
    for (const TimeDirectory& t : times) {
        fmt::print("Removing {}\n", t.path.string());
        std::filesystem::remove_all(t.path);
    }
}

TimeDirectory selectStartTime(const std::filesystem::path& caseDirectory, const Dictionary& controlDict) {
    std::vector<std::filesystem::path> withoutState;
    const std::vector<TimeDirectory> times = findTimeDirectories(caseDirectory, &withoutState);
    for (const auto& skipped : withoutState)
        fmt::print("warning: skipping the time directory {}: it holds no fluid.vtu or fluid.pvtu\n", skipped.string());
    if (times.empty())
        throw FatalError("error: case '" + caseDirectory.string() +
                         "' has no time directory with a fluid.vtu or fluid.pvtu state; run generateParticles first to write 0/");
    const std::string startFrom = controlDict.getOrDefault<std::string>("startFrom", "latestTime");
    if (startFrom == "latestTime") return times.back();
    if (startFrom == "startTime") {
        const double startTime = controlDict.get<double>("startTime");
        for (const TimeDirectory& t : times)
            if (std::abs(t.time - startTime) <= 1e-9 * std::max(1.0, std::abs(startTime))) return t;
        std::string valid;
        for (const TimeDirectory& t : times) (valid += ' ') += timeName(t.time);
        controlDict.fail("startTime", "no time directory " + timeName(startTime) + " with a fluid.vtu or fluid.pvtu; written times are:" + valid);
    }
    controlDict.fail("startFrom", "expected latestTime or startTime, found '" + startFrom + "'");
}

void removeIncompleteOutput(const std::filesystem::path& caseDirectory) {
    // What the atomic writes name their temporaries: a time directory, or a file of a kind
    // sphkit writes; anything else with a similar name is the user's and stays.
    static const std::regex leftover(R"(\.([0-9.eE+-]+|.+\.(vtu|pvd|csv|dat))\.(tmp|old)([0-9]+))");
    std::error_code ec;
    std::vector<std::filesystem::path> found;
    for (const auto& item : std::filesystem::recursive_directory_iterator(caseDirectory, ec)) {
        std::smatch match;
        const std::string name = item.path().filename().string();
        if (!std::regex_match(name, match, leftover)) continue;
        // A process that is still running (another solver on this case) is not interrupted.
        const long writer = std::strtol(match[4].str().c_str(), nullptr, 10);
        const bool writerGone =
            writer > 0 && writer <= std::numeric_limits<pid_t>::max() && ::kill(static_cast<pid_t>(writer), 0) != 0 && errno == ESRCH;
        if (writerGone) found.push_back(item.path());
    }
    for (const auto& path : found) {
        fmt::print("Removing {}, left incomplete by an interrupted run\n", path.string());
        std::filesystem::remove_all(path, ec);
    }
}

Dictionary readCaseDictionary(const std::filesystem::path& caseDirectory, const std::string& relative) {
    return Dictionary::fromFile(caseDirectory / relative, std::filesystem::path(relative).filename().string());
}

}  // namespace sph
