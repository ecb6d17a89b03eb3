// The parent's side of the OpenGL peer: start `facet bench --peer` with LP_NUM_THREADS set and a
// socket as its stdin and stdout, then ask for measurements one line at a time.

#include <fcntl.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "gl_peer_process.hpp"

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

Error peerError(const std::string& message) {
    return Error{{"OpenGL peer", 0}, message};
}

}  // namespace

struct GlPeerProcess::State {
    pid_t pid = 0;
    int socket = -1;     ///< ours of the pair: commands out, the peer's lines in
    FILE* in = nullptr;  ///< reads `socket` (a duplicate) line by line
    std::string renderer;
    bool finished = false;

    /// The next protocol line; the event and the rest, or an Error when the peer ended.
    Result<std::pair<std::string, std::string>> next() {
        char* buf = nullptr;
        std::size_t cap = 0;
        for (ssize_t n; (n = getline(&buf, &cap, in)) > 0;) {
            std::string line(buf, static_cast<std::size_t>(n));
            while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
            if (line.rfind(kPrefix, 0) != 0) continue;  // the driver's chatter
            std::free(buf);
            std::istringstream s(line.substr(kPrefix.size()));
            std::string event, rest;
            s >> event;
            std::getline(s >> std::ws, rest);
            if (event == "error") return peerError(rest.empty() ? "unspecified error" : rest);
            return std::make_pair(event, rest);
        }
        std::free(buf);
        if (Status st = finish(); !st) return st.error();
        return peerError("ended without answering");
    }

    Status finish() {
        if (finished) return {};
        finished = true;
        // Ending its input ends the peer's loop.
        shutdown(socket, SHUT_WR);
        if (in) std::fclose(in);
        close(socket);
        int status = 0;
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
        if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {};
        return peerError(WIFSIGNALED(status)
                             ? "killed by signal " + std::to_string(WTERMSIG(status))
                             : "exited with status " + std::to_string(WEXITSTATUS(status)));
    }
};

Result<GlPeerProcess> GlPeerProcess::start(const BenchOptions& o, int lpThreads) {
    int fds[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0)
        return peerError(std::string("socketpair: ") + std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    // dup2 clears close-on-exec on the copies: the peer's stdin and stdout are its end of the
    // pair, nothing else leaks.
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDIN_FILENO);
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
        return peerError(std::string("cannot start: ") + std::strerror(rc));
    }
    auto state = std::make_unique<State>();
    state->pid = pid;
    state->socket = fds[0];
    const int readFd = fcntl(fds[0], F_DUPFD_CLOEXEC, 0);
    state->in = readFd >= 0 ? fdopen(readFd, "r") : nullptr;
    GlPeerProcess peer(std::move(state));
    if (!peer.state_->in) {
        if (readFd >= 0) close(readFd);
        (void)peer.finish();
        return peerError("cannot read the peer's output");
    }
    Result<std::pair<std::string, std::string>> info = peer.state_->next();
    if (!info) return info.error();
    if (info->first != "info") return peerError("said '" + info->first + "' before 'info'");
    peer.state_->renderer = info->second;
    return peer;
}

GlPeerProcess::GlPeerProcess(std::unique_ptr<State> state) : state_(std::move(state)) {}
GlPeerProcess::GlPeerProcess(GlPeerProcess&& other) noexcept = default;
GlPeerProcess& GlPeerProcess::operator=(GlPeerProcess&& other) noexcept = default;

GlPeerProcess::~GlPeerProcess() {
    if (state_) (void)state_->finish();
}

const std::string& GlPeerProcess::renderer() const {
    return state_->renderer;
}

Result<FrameTimes> GlPeerProcess::measure(const std::string& caseName, const std::string& config) {
    if (state_->finished) return peerError("has ended");
    const std::string command = "run " + caseName + " " + config + "\n";
    // MSG_NOSIGNAL: a peer that died is an error value here, not a SIGPIPE for the bench.
    if (send(state_->socket, command.data(), command.size(), MSG_NOSIGNAL) !=
        static_cast<ssize_t>(command.size())) {
        const std::string why = std::strerror(errno);
        if (Status st = state_->finish(); !st) return st.error();
        return peerError("cannot send: " + why);
    }
    Result<std::pair<std::string, std::string>> line = state_->next();
    if (!line) return line.error();
    std::istringstream in(line->second);
    std::string name, conf;
    FrameTimes t;
    in >> name >> conf >> t.frames >> t.median >> t.min >> t.max;
    if (line->first != "result" || !in || name != caseName || conf != config)
        return peerError("answered '" + line->first + " " + line->second + "' to '" +
                         command.substr(0, command.size() - 1) + "'");
    return t;
}

Status GlPeerProcess::finish() {
    return state_->finish();
}

}  // namespace facet::app
