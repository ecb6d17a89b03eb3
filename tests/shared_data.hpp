#pragma once
// The one rule for a test that cannot run because something it needs is missing: the course and
// public test data (in ../shared beside the clone, FACET_SHARED_DIR), an OpenGL context, or a
// tool of the window tests (xvfb-run, xdotool, xprop). A fresh local clone or a machine without
// a display may lack them, so there such a test is skipped and says what is missing (`make test`
// ends with the skips and why). Under CI (CI=true) all of them are part of the setup, and a run
// that skipped those tests would pass while checking nothing, so it fails instead.

#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

namespace facet::test {

/// A file or folder under FACET_SHARED_DIR/data, e.g. sharedData("course/brick.jpg").
inline std::string sharedData(const std::string& relative) {
    return std::string(FACET_SHARED_DIR) + "/data/" + relative;
}

/// True when a missing prerequisite (shared file, OpenGL context, display tool) must fail the
/// test rather than skip it: under CI=true.
inline bool sharedDataRequired() {
    const char* ci = std::getenv("CI");
    return ci != nullptr && std::string_view(ci) == "true";
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
    return missingPrerequisite("shared data missing: " + path +
                               " (FACET_SHARED_DIR is " FACET_SHARED_DIR
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
