#pragma once
// The course and public test data live outside the repository, in ../shared beside the clone
// (FACET_SHARED_DIR). A fresh local clone may not have it, so there a test that needs a missing
// file is skipped and says which file; under CI (CI=true) the data is part of the setup, and a
// run that skipped those tests would pass while checking nothing, so it fails instead.

#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

namespace facet::test {

/// A file or folder under FACET_SHARED_DIR/data, e.g. sharedData("course/brick.jpg").
inline std::string sharedData(const std::string& relative) {
    return std::string(FACET_SHARED_DIR) + "/data/" + relative;
}

/// True when a missing shared file must fail the test rather than skip it.
inline bool sharedDataRequired() {
    const char* ci = std::getenv("CI");
    return ci != nullptr && std::string_view(ci) == "true";
}

/// Empty when `path` exists, else why a test that needs it cannot run.
inline std::string missingSharedData(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::exists(path, ec)) return {};
    std::string why = "shared data missing: " + path +
                      " (FACET_SHARED_DIR is " FACET_SHARED_DIR
                      "; the course and test data belong in ../shared beside the clone)";
    if (sharedDataRequired()) why += "; CI=true, so this is a failure, not a skip";
    return why;
}

}  // namespace facet::test

/// Ends the current test (or its SetUp) when the shared file or folder `path` is missing: a
/// failure under CI=true, a skip otherwise, the message naming the path either way.
#define REQUIRE_SHARED_DATA(path)                                                  \
    do {                                                                           \
        const std::string facet_missing_ = ::facet::test::missingSharedData(path); \
        if (facet_missing_.empty()) break;                                         \
        if (::facet::test::sharedDataRequired())                                   \
            FAIL() << facet_missing_;                                              \
        else                                                                       \
            GTEST_SKIP() << facet_missing_;                                        \
    } while (false)
