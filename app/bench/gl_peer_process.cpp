// The parent's side of the OpenGL peer: start `facet bench --peer` with LP_NUM_THREADS set, read
// its lines as they come, and turn them into events.

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "gl_peer.hpp"

extern char** environ;

namespace facet::app {
namespace {

const std::string kPrefix = "facet-peer ";

/// The peer's command line: the options that select the suite and time it, nothing else.
std::vector<std::string> peerArgs(const BenchOptions& o) {
    std::vector<std::string> a = {"facet", "bench", "--peer"};
    if (o.quick) a.push_back("--quick");
    if (o.scaling) a.push_back("--scaling");
    if (!o.cases.empty()) a.insert(a.end(), {"--cases", o.cases});
    if (!o.configs.empty()) a.insert(a.end(), {"--configs", o.configs});
    if (!o.images.empty()) a.insert(a.end(), {"--images", o.images});
    const FramePlan plan = framePlan(o);
    a.insert(a.end(),
             {"--shared", sharedDir(o), "--frames", std::to_string(plan.frames), "--warmup",
              std::to_string(plan.warmup), "--budget", std::to_string(plan.budgetSeconds)});
    return a;
}

/// This process's environment with LP_NUM_THREADS replaced.
std::vector<std::string> peerEnvironment(int lpThreads) {
    std::vector<std::string> env;
    for (char** e = environ; *e; ++e)
        if (std::strncmp(*e, "LP_NUM_THREADS=", 15) != 0) env.emplace_back(*e);
    env.push_back("LP_NUM_THREADS=" + std::to_string(lpThreads));
    return env;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
    std::vector<char*> p;
    for (std::string& s : strings) p.push_back(s.data());
    p.push_back(nullptr);
    return p;
}

/// Handles one line; returns the peer's error message when the line is one.
std::string dispatch(const std::string& line, const PeerEvents& events) {
    if (line.rfind(kPrefix, 0) != 0) return "";
    std::istringstream in(line.substr(kPrefix.size()));
    std::string event, caseName, config;
    in >> event;
    if (event == "info") {
        std::string rest;
        std::getline(in >> std::ws, rest);
        events.info(rest);
    } else if (event == "start") {
        in >> caseName >> config;
        events.start(caseName, config);
    } else if (event == "result") {
        FrameTimes t;
        in >> caseName >> config >> t.frames >> t.median >> t.min >> t.max;
        events.result(caseName, config, t);
    } else if (event == "error") {
        std::string rest;
        std::getline(in >> std::ws, rest);
        return rest.empty() ? "unspecified error" : rest;
    }
    return "";
}

}  // namespace

Status runGlPeerProcess(const BenchOptions& o, int lpThreads, const PeerEvents& events) {
    const Error spawnFailed{{"OpenGL peer", 0}, ""};
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0)
        return Error{spawnFailed.loc, std::string("pipe: ") + std::strerror(errno)};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    // dup2 clears close-on-exec on the copy: the peer's stdout is the pipe, nothing else leaks.
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
    std::vector<std::string> args = peerArgs(o), env = peerEnvironment(lpThreads);
    std::vector<char*> argv = pointers(args), envp = pointers(env);
    pid_t pid = 0;
    // /proc/self/exe is this very binary, wherever it was started from.
    const int rc = posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    if (rc != 0) {
        close(fds[0]);
        return Error{spawnFailed.loc, std::string("cannot start: ") + std::strerror(rc)};
    }
    std::string error;
    FILE* in = fdopen(fds[0], "r");
    char* buf = nullptr;
    std::size_t cap = 0;
    for (ssize_t n; in && (n = getline(&buf, &cap, in)) > 0;) {
        std::string line(buf, static_cast<std::size_t>(n));
        while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
        if (std::string e = dispatch(line, events); !e.empty()) error = e;
    }
    std::free(buf);
    if (in)
        std::fclose(in);
    else
        close(fds[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!error.empty()) return Error{spawnFailed.loc, error};
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return Error{spawnFailed.loc,
                     WIFSIGNALED(status)
                         ? "killed by signal " + std::to_string(WTERMSIG(status))
                         : "exited with status " + std::to_string(WEXITSTATUS(status))};
    return {};
}

}  // namespace facet::app
