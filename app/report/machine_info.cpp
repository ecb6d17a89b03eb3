#include "machine_info.hpp"

#include <sys/utsname.h>

#include <ctime>
#include <fstream>
#include <thread>

namespace facet::app {
namespace {

std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("model name", 0) != 0) continue;
        const auto colon = line.find(':');
        if (colon == std::string::npos) break;
        const auto start = line.find_first_not_of(" \t", colon + 1);
        return start == std::string::npos ? "unknown" : line.substr(start);
    }
    return "unknown";
}

std::string compilerName() {
#if defined(__clang__)
    return "Clang " __clang_version__;
#elif defined(__GNUC__)
    return "GCC " __VERSION__;
#else
    return "unknown";
#endif
}

std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    if (!(in >> one >> five >> fifteen)) return "unknown";
    return one + " " + five + " " + fifteen;
}

std::string now() {
    const std::time_t t = std::time(nullptr);
    std::tm local{};
    localtime_r(&t, &local);
    char buf[64];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S%z", &local);
    return buf;
}

}  // namespace

MachineInfo collectMachineInfo() {
    MachineInfo m;
    m.date = now();
    m.cpu = cpuModel();
    m.cores = static_cast<int>(std::thread::hardware_concurrency());
    m.compiler = compilerName();
#ifdef NDEBUG
    m.build = "optimised (NDEBUG)";
#else
    m.build = "debug (assertions on)";
#endif
    utsname u{};
    m.load = loadAverage();
    m.kernel = uname(&u) == 0 ? std::string(u.sysname) + " " + u.release : "unknown";
    return m;
}

}  // namespace facet::app
