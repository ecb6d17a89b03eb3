// LoadControl: the loaders' progress and cancellation (issue 14). Progress only goes up and ends
// at 1; a cancel, before the load or from another thread while it reads, ends it with the
// cancelled error and no mesh; and a load with the hook gives the same mesh as one without.

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <unistd.h>

#include "facet/load_control.hpp"
#include "facet/mesh_io.hpp"
#include "facet/procedural.hpp"
#include "facet/scene_io.hpp"
#include "facet/texture.hpp"
#include "large_mesh.hpp"
#include "shared_data.hpp"

namespace {

namespace fs = std::filesystem;
using namespace facet;

// The process id keeps two builds' runs on one machine apart.
std::string tempPath(const std::string& name) {
    return (fs::path(testing::TempDir()) /
            ("facet_load_control_test_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

void writeText(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// One large OBJ and OFF for the whole suite: writing them is most of the suite's time.
class LoadControlTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        bigObj = tempPath("big.obj");
        writeText(bigObj, facet::test::gridObj(400));  // 320,000 triangles, about 20 MB
        bigOff = tempPath("big.off");
        ASSERT_TRUE(writeOff(makeUvSphere(400, 400), bigOff));  // 320,000 triangles
    }
    static void TearDownTestSuite() {
        fs::remove(bigObj);
        fs::remove(bigOff);
    }
    static inline std::string bigObj;
    static inline std::string bigOff;
};

// Every report, in order; a cancel flag the test may set.
struct Recorder {
    std::vector<float> reports;
    std::atomic<bool> stop{false};
    LoadControl control() {
        LoadControl c;
        c.progress = [this](float f) { reports.push_back(f); };
        c.cancel = &stop;
        return c;
    }
};

// Rising from the first report to exactly 1 at the end, in many steps but thinned.
void expectRisesToOne(const std::vector<float>& reports, std::size_t atLeast) {
    ASSERT_GE(reports.size(), atLeast);
    EXPECT_LE(reports.size(), 1100u);  // thinned to steps of 1/1000
    EXPECT_GE(reports.front(), 0.0f);
    for (std::size_t i = 1; i < reports.size(); ++i)
        ASSERT_GT(reports[i], reports[i - 1]) << "report " << i;
    EXPECT_EQ(reports.back(), 1.0f);
}

TEST_F(LoadControlTest, ProgressRisesToOneThroughEveryPhaseOfAnObj) {
    Recorder r;
    const LoadControl c = r.control();
    Result<Mesh> mesh = loadObj(bigObj, &c);
    ASSERT_TRUE(mesh) << mesh.error().what();
    expectRisesToOne(r.reports, 100);
    // Each phase (read, check, parse, build) reports inside its share, not in one jump.
    const std::pair<float, float> inside[] = {
        {0.005f, 0.015f}, {0.1f, 0.15f}, {0.5f, 0.55f}, {0.9f, 0.95f}};
    for (const std::pair<float, float>& range : inside) {
        EXPECT_TRUE(std::any_of(r.reports.begin(), r.reports.end(),
                                [&range](float f) { return f > range.first && f < range.second; }))
            << "no report between " << range.first << " and " << range.second;
    }
}

TEST_F(LoadControlTest, ProgressRisesToOneForOffScenesAndBareMeshes) {
    {
        Recorder r;
        const LoadControl c = r.control();
        ASSERT_TRUE(loadOff(bigOff, &c));
        expectRisesToOne(r.reports, 100);
    }
    {
        Recorder r;
        const LoadControl c = r.control();
        Result<Scene> scene = openSceneFile(bigObj, 640, 360, &c);
        ASSERT_TRUE(scene) << scene.error().what();
        expectRisesToOne(r.reports, 100);
    }
    const std::string spot = facet::test::sharedData("scenes/spot_1280x720.scene");
    REQUIRE_SHARED_DATA(spot);
    Recorder r;
    const LoadControl c = r.control();
    Result<Scene> scene = loadScene(spot, &c);
    ASSERT_TRUE(scene) << scene.error().what();
    ASSERT_TRUE(scene->texture);
    expectRisesToOne(r.reports, 10);
}

TEST_F(LoadControlTest, TheHookDoesNotChangeWhatIsLoaded) {
    Recorder r;
    const LoadControl c = r.control();
    for (const std::string& file : {bigObj, bigOff}) {
        Result<Mesh> plain = loadMesh(file);
        Result<Mesh> hooked = loadMesh(file, &c);
        ASSERT_TRUE(plain && hooked);
        EXPECT_GT(plain->triangleCount(), 300000u);
        EXPECT_TRUE(*plain == *hooked) << file;
    }
    const std::string spot = facet::test::sharedData("models/spot_triangulated.obj");
    REQUIRE_SHARED_DATA(spot);
    Result<Mesh> plain = loadObj(spot);
    Result<Mesh> hooked = loadObj(spot, &c);
    ASSERT_TRUE(plain && hooked);
    EXPECT_FALSE(plain->positionIds.empty());  // seams: the split-vertex path ran
    EXPECT_TRUE(*plain == *hooked);
}

TEST_F(LoadControlTest, ACancelBeforeTheStartLoadsNothing) {
    Recorder r;
    r.stop = true;
    const LoadControl c = r.control();
    const std::string texture = facet::test::sharedData("models/spot_texture.png");
    const auto expectCancelled = [](const Error& e, const std::string& file) {
        EXPECT_TRUE(e.cancelled) << e.what();
        EXPECT_EQ(e.loc.file, file);
        EXPECT_EQ(e.what(), file + ": loading cancelled");
    };
    Result<Mesh> obj = loadObj(bigObj, &c);
    ASSERT_FALSE(obj);
    expectCancelled(obj.error(), bigObj);
    Result<Mesh> off = loadOff(bigOff, &c);
    ASSERT_FALSE(off);
    expectCancelled(off.error(), bigOff);
    Result<Scene> bare = openSceneFile(bigObj, 640, 360, &c);
    ASSERT_FALSE(bare);
    expectCancelled(bare.error(), bigObj);
    // An error in the file is not a cancel.
    Result<Mesh> bad = loadOff(std::string(FACET_TEST_DATA) + "/off_nan.off");
    ASSERT_FALSE(bad);
    EXPECT_FALSE(bad.error().cancelled);
    REQUIRE_SHARED_DATA(texture);
    Result<Texture> image = loadTexture(texture, &c);
    ASSERT_FALSE(image);
    expectCancelled(image.error(), texture);
}

TEST_F(LoadControlTest, ACancelDuringTheLoadStopsItWhereItIs) {
    // Cancelled from the progress report itself: deterministic, at a known point of each phase.
    for (const std::string& file : {bigObj, bigOff}) {
        for (const float at : {0.03f, 0.2f, 0.5f, 0.9f}) {
            Recorder r;
            LoadControl c = r.control();
            c.progress = [&r, at](float f) {
                r.reports.push_back(f);
                if (f >= at) r.stop = true;
            };
            Result<Mesh> mesh = loadMesh(file, &c);
            ASSERT_FALSE(mesh) << file << " at " << at;
            EXPECT_TRUE(mesh.error().cancelled);
            // Nothing reported after the report that cancelled.
            ASSERT_GE(r.reports.size(), 2u);
            EXPECT_GE(r.reports.back(), at);
            EXPECT_LT(r.reports[r.reports.size() - 2], at) << file << " at " << at;
        }
    }
}

TEST_F(LoadControlTest, ACancelFromAnotherThreadStopsALargeReadQuickly) {
    std::atomic<float> progress{0.0f};
    std::atomic<bool> stop{false};
    LoadControl c;
    c.progress = [&progress](float f) { progress = f; };
    c.cancel = &stop;
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    Clock::time_point returned;
    std::optional<Result<Scene>> result;
    std::thread worker([&] {
        result.emplace(openSceneFile(bigObj, 640, 360, &c));
        returned = Clock::now();
    });
    while (progress.load() < 0.1f) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    stop = true;
    const Clock::time_point cancelled = Clock::now();
    const float at = progress.load();
    worker.join();
    ASSERT_TRUE(result.has_value());
    ASSERT_FALSE(*result);
    EXPECT_TRUE(result->error().cancelled) << result->error().what();
    // It stopped where it was: at most one chunk or a few thousand lines further.
    EXPECT_LT(progress.load(), at + 0.05f);
    const auto ms = [](auto d) { return std::chrono::duration<double, std::milli>(d).count(); };
    std::printf("cancelled at %.0f %% after %.0f ms; returned %.1f ms later\n", 100.0 * at,
                ms(cancelled - start), ms(returned - cancelled));
}

}  // namespace
