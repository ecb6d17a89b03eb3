#pragma once
// The one rule for a test that cannot run because something it needs is missing: the course and
// public test data (in ../shared beside the clone, FACET_SHARED_DIR), an OpenGL context, or a
// tool of the window tests (xvfb-run, xdotool, xprop). A fresh local clone or a machine without
// a display may lack them, so there such a test is skipped and says what is missing (`make test`
// ends with the skips and why). Under CI (CI=true) all of them are part of the setup, and a run
// that skipped those tests would pass while checking nothing, so it fails instead.
// The environment variable FACET_SHARED_DIR, when set, names another shared folder than the one
// the build was configured with (a copy elsewhere, or a folder that is not there to see the rule
// at work).

#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

namespace facet::test {

/// The shared folder: $FACET_SHARED_DIR when set, else the one the build was configured with.
inline std::string sharedDir() {
    const char* dir = std::getenv("FACET_SHARED_DIR");
    return dir != nullptr && *dir != '\0' ? std::string(dir) : std::string(FACET_SHARED_DIR);
}

/// A file or folder under the shared folder's data/, e.g. sharedData("course/brick.jpg").
inline std::string sharedData(const std::string& relative) {
    return sharedDir() + "/data/" + relative;
}

/// The course's folder of scenes, meshes and textures under the shared data.
inline std::string courseDir() {
    return sharedData("course");
}

/// Whether `program` is on PATH (a tool a test runs: xvfb-run, xdotool, xprop, gnuplot).
inline bool haveTool(const std::string& program) {
    return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

/// True when a missing prerequisite (shared file, OpenGL context, display tool) must fail the
/// test rather than skip it: under CI=true.
inline bool sharedDataRequired() {
    const char* ci = std::getenv("CI");
    return ci != nullptr && std::string_view(ci) == "true";
}

/// Whether gnuplot, which draws the charts of `facet bench`, `accuracy` and `sweeps`, is on PATH.
inline bool haveGnuplot() {
    return haveTool("gnuplot");
}

/// `why` a test cannot run, with the note that it fails under CI=true.
inline std::string missingPrerequisite(std::string why) {
    if (sharedDataRequired()) why += "; CI=true, so this is a failure, not a skip";
    return why;
}

/// Empty when `path` exists, else why a test that needs it cannot run.
inline std::string missingSharedData(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::exists(path, ec)) return {};
    return missingPrerequisite("shared data missing: " + path + " (the shared folder is " +
                               sharedDir() +
                               "; the course and test data belong in ../shared beside the clone)");
}

}  // namespace facet::test

/// Ends the current test (or its SetUp) with `message` (from missingPrerequisite or
/// missingSharedData): a failure under CI=true, a skip otherwise. The one place that decides.
#define FACET_END_FOR_MISSING(message)           \
    do {                                         \
        if (::facet::test::sharedDataRequired()) \
            FAIL() << (message);                 \
        else                                     \
            GTEST_SKIP() << (message);           \
    } while (false)

/// Ends the current test when `available` is false, saying `why` (a missing OpenGL context or
/// display tool): a failure under CI=true, a skip otherwise.
#define REQUIRE_PREREQUISITE(available, why)                            \
    do {                                                                \
        if (available) break;                                           \
        FACET_END_FOR_MISSING(::facet::test::missingPrerequisite(why)); \
    } while (false)

/// Ends the current test (or its SetUp) when the shared file or folder `path` is missing: a
/// failure under CI=true, a skip otherwise, the message naming the path either way.
#define REQUIRE_SHARED_DATA(path)                                                  \
    do {                                                                           \
        const std::string facet_missing_ = ::facet::test::missingSharedData(path); \
        if (facet_missing_.empty()) break;                                         \
        FACET_END_FOR_MISSING(facet_missing_);                                     \
    } while (false)

/// Ends a test that left out its chart checks for want of gnuplot (after the checks that ran
/// without it): a failure under CI=true, a skip otherwise.
#define REQUIRE_GNUPLOT()                                    \
    REQUIRE_PREREQUISITE(::facet::test::haveGnuplot(),       \
                         "gnuplot is not installed (Debian " \
                         "package gnuplot-nox), so the chart checks did not run")
