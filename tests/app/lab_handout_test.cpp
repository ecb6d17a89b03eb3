// The lab kit's handout (`make lab-handout`, docs/lab.md): made into a temporary folder and built
// on its own, as a student would, which builds facet from this clone again (minutes, so a test
// of its own with a long timeout).

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "lab/steps.hpp"
#include "run_process.hpp"
#include "shared_data.hpp"
#include "test_files.hpp"

namespace {

namespace fs = std::filesystem;
using facet::test::courseDir;
using facet_test::countOf;

// ---- the handout ------------------------------------------------------------------------------

using facet::test::readFile;
using facet::test::writeFile;

// The text of the function whose definition starts with `signature`, up to its closing brace
// at the start of a line.
std::string functionText(const std::string& file, const std::string& signature) {
    const std::size_t begin = file.find(signature);
    if (begin == std::string::npos) return {};
    const std::size_t end = file.find("\n}\n", begin);
    return end == std::string::npos ? std::string() : file.substr(begin, end + 3 - begin);
}

std::string replaceFunction(const std::string& file, const std::string& signature,
                            const std::string& replacement) {
    const std::string old = functionText(file, signature);
    std::string out = file;
    out.replace(out.find(old), old.size(), replacement);
    return out;
}

// A handout made by `make lab-handout`, built on its own in a temporary folder (this builds
// facet from this clone too: minutes), its stubs all "not started"; one step written wrong
// fails with the course's hint; written right it passes and the next step is the first failure.
TEST(LabHandout, BuildsOnItsOwnAndChecksOneStepAtATime) {
    REQUIRE_SHARED_DATA(courseDir() + "/example0.scene");
    const fs::path root = fs::path(FACET_SOURCE_DIR);
    // A fixed name per clone: the compiler cache then finds facet's objects from the previous run
    // (the paths in the compile lines stay the same), and two clones testing at once do not build
    // in each other's folder.
    const fs::path tmp =
        fs::temp_directory_path() /
        ("facet-lab-handout-test-" + std::to_string(std::hash<std::string>{}(FACET_SOURCE_DIR)));
    fs::remove_all(tmp);
    fs::create_directories(tmp);
    const fs::path dir = tmp / "handout";

    facet_test::Outcome made = facet_test::runCommand(
        "make -C " + root.string() + " --no-print-directory lab-handout DIR=" + dir.string() +
        " COURSE=" + courseDir());
    ASSERT_EQ(made.exitCode, 0) << made.out;
    for (const char* f :
         {"CMakeLists.txt", "Makefile", "README.md", "steps/transformation.cpp",
          "steps/rasterizer.cpp", "steps/depth_buffer.cpp", "steps/mesh.cpp", "steps/lights.cpp",
          "steps/texture.cpp", "steps/perspective_rasterizer.cpp"})
        EXPECT_TRUE(fs::exists(dir / f)) << f;
    // No solution in it: every step file is the stub.
    for (const auto& e : fs::directory_iterator(dir / "steps"))
        EXPECT_NE(readFile(e.path()).find("otStarted"), std::string::npos) << e.path();
    EXPECT_FALSE(fs::exists(dir / "solution"));
    // Refuses to write over a folder with files in it.
    EXPECT_NE(facet_test::runCommand("make -C " + root.string() +
                                     " --no-print-directory lab-handout DIR=" + dir.string())
                  .exitCode,
              0);

    const std::string build = (dir / "build").string();
    const facet_test::Outcome configured =
        facet_test::runCommand("cmake -S " + dir.string() + " -B " + build +
                               " -G Ninja -DCMAKE_BUILD_TYPE=Release -DFACET_BUILD_VIEWER=OFF");
    ASSERT_EQ(configured.exitCode, 0) << configured.out;
    const std::string check = build + "/facet/lab/lab_check " + courseDir();
    const auto buildAndCheck = [&] {
        const facet_test::Outcome b =
            facet_test::runCommand("cmake --build " + build + " --target lab_check");
        EXPECT_EQ(b.exitCode, 0) << b.out;
        return facet_test::runCommand(check);
    };

    const facet_test::Outcome stubs = buildAndCheck();
    EXPECT_EQ(stubs.exitCode, 1) << stubs.out;
    EXPECT_EQ(countOf(stubs.out, " not started ("), lab::kStepCount) << stubs.out;

    // setLookAt written with the camera's axis backwards: the first failure, with the hint.
    const fs::path student = dir / "steps/transformation.cpp";
    const std::string stub = readFile(student);
    const std::string solution =
        functionText(readFile(root / "lab/solution/transformation.cpp"), "glm::dmat4 setLookAt(");
    ASSERT_FALSE(solution.empty());
    std::string wrong = solution;
    wrong.replace(wrong.find("lookAt - eye"), 12, "eye - lookAt");
    writeFile(student, replaceFunction(stub, "glm::dmat4 setLookAt(", wrong));
    const facet_test::Outcome failing = buildAndCheck();
    EXPECT_EQ(failing.exitCode, 1) << failing.out;
    EXPECT_NE(failing.out.find("setLookAt                                FAILED"),
              std::string::npos)
        << failing.out;
    EXPECT_NE(failing.out.find("the camera's Z axis must point from the eye to the look-at point"),
              std::string::npos)
        << failing.out;
    EXPECT_EQ(countOf(failing.out, " not started ("), lab::kStepCount - 1) << failing.out;

    // The solution's setLookAt: that step passes and setProjection is the first failure.
    writeFile(student, replaceFunction(stub, "glm::dmat4 setLookAt(", solution));
    const facet_test::Outcome fixed = buildAndCheck();
    EXPECT_EQ(fixed.exitCode, 1) << fixed.out;
    EXPECT_NE(fixed.out.find(" 1  setLookAt                                ok"), std::string::npos)
        << fixed.out;
    EXPECT_NE(fixed.out.find(" 2  setProjection                            not started"),
              std::string::npos)
        << fixed.out;
    EXPECT_EQ(countOf(fixed.out, "FAILED"), 0) << fixed.out;
    EXPECT_NE(fixed.out.find("1 of 12 steps pass"), std::string::npos) << fixed.out;
    fs::remove_all(tmp);
}

}  // namespace
