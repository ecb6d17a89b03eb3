#pragma once
// Files the tests read and write: the repository's own small test files (tests/data), whole files
// as bytes.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace facet::test {

/// A file of the repository's tests/data folder, e.g. testData("off_nan.off").
inline std::string testData(const std::string& name) {
    return std::string(FACET_TEST_DATA) + "/" + name;
}

/// The whole file as bytes; empty when it cannot be read.
inline std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Writes `bytes` as the whole file.
inline void writeFile(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}
}  // namespace facet::test
