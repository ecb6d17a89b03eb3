#pragma once
// Running the project's own programs (facet, facet-view) as real processes from a test and
// reading what they print: the CLI, inspector and viewer window tests share it.

#include <sys/wait.h>

#include <array>
#include <cstddef>
#include <cstdio>
#include <string>

namespace facet_test {

/// A finished process: its exit code (-1 if it did not exit normally) and its output.
struct Outcome {
    int exitCode = -1;
    std::string out;  // stdout and stderr together
};

/// Runs `cmd` through the shell and waits for it.
inline Outcome runCommand(const std::string& cmd) {
    Outcome r;
    FILE* p = popen((cmd + " 2>&1").c_str(), "r");
    if (!p) return r;
    std::array<char, 4096> buf{};
    while (std::fgets(buf.data(), static_cast<int>(buf.size()), p)) r.out += buf.data();
    const int status = pclose(p);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

/// How many times `what` occurs in `text` (overlapping occurrences count), e.g. the lines of a
/// report in a process's output.
inline int countOf(const std::string& text, const std::string& what) {
    int n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

}  // namespace facet_test
