// `facet accuracy` and `facet sweeps` as a user runs them (real processes, real files): where
// they write (a new folder unless told, never over files they were not asked to replace), the
// progress they show, --quick, bare meshes, and the rule that only methods coarser than the
// ground truth are measured, which the viewer's Compare panel shares (app::methodsBelowTruth).

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "accuracy/accuracy_methods.hpp"
#include "accuracy/run_output.hpp"
#include "accuracy_job.hpp"
#include "facet/camera.hpp"
#include "facet/scene_io.hpp"
#include "run_process.hpp"
#include "shared_data.hpp"
#include "test_files.hpp"

namespace {

namespace fs = std::filesystem;

using facet::Result;
using facet_test::Outcome;

/// Runs facet with `args` in the folder `cwd` (stdout and stderr together; not a terminal, so
/// the progress comes as whole lines, as in a log).
Outcome runIn(const fs::path& cwd, const std::string& args) {
    return facet_test::runCommand("cd '" + cwd.string() + "' && " + FACET_CLI + " " + args);
}

int countLines(const std::string& s) {
    return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

using facet::test::haveGnuplot;

using facet::test::readFile;

bool isPng(const fs::path& path) {
    const std::string b = readFile(path);
    return b.size() > 8 && b.compare(1, 3, "PNG") == 0;
}

/// The folders in `dir` whose names start with `prefix`.
std::vector<fs::path> foldersStartingWith(const fs::path& dir, const std::string& prefix) {
    std::vector<fs::path> found;
    for (const fs::directory_entry& e : fs::directory_iterator(dir))
        if (e.is_directory() && e.path().filename().string().rfind(prefix, 0) == 0)
            found.push_back(e.path());
    std::sort(found.begin(), found.end());
    return found;
}

/// Runs `args` twice in `cwd`: each run must succeed, and the two must leave two folders named
/// `prefix`…, returned in `runs` with both runs' output in `out`.
void runTwice(const fs::path& cwd, const std::string& args, const std::string& prefix,
              std::vector<fs::path>& runs, std::string& out) {
    const Outcome first = runIn(cwd, args);
    ASSERT_EQ(first.exitCode, 0) << first.out;
    const Outcome second = runIn(cwd, args);
    ASSERT_EQ(second.exitCode, 0) << second.out;
    runs = foldersStartingWith(cwd, prefix);
    ASSERT_EQ(runs.size(), 2u) << first.out << second.out;
    out = first.out + second.out;
}

/// A CSV without its `#` lines: the header first, then the rows, split at commas.
struct Csv {
    int comments = 0;
    std::vector<std::string> commentText;
    std::vector<std::vector<std::string>> rows;
};

Csv readCsv(const fs::path& path) {
    Csv csv;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("#", 0) == 0) {
            ++csv.comments;
            csv.commentText.push_back(line);
            continue;
        }
        std::vector<std::string> cells;
        std::stringstream ss(line);
        for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
        csv.rows.push_back(cells);
    }
    return csv;
}

/// The accuracy CSV's methods (column 3), in order.
std::vector<std::string> methodsIn(const Csv& csv) {
    std::vector<std::string> names;
    for (std::size_t k = 1; k < csv.rows.size(); ++k) names.push_back(csv.rows[k].at(2));
    return names;
}

class AccuracyCli : public ::testing::Test {
  protected:
    fs::path dir =
        fs::temp_directory_path() / ("facet_accuracy_cli_test_" + std::to_string(::getpid()));
    void SetUp() override { fs::create_directories(dir); }
    void TearDown() override { fs::remove_all(dir); }
    std::string chartFlag() const { return haveGnuplot() ? "" : " --no-chart"; }
};

// Run where the committed charts live (a folder with docs/accuracy and docs/sweeps, as in the
// repository), neither command touches them: each run makes a new folder of its own, a second
// run in the same second another one.
TEST_F(AccuracyCli, DefaultFolderIsNewAndCommittedFilesStayUntouched) {
    const std::string wall = facet::test::sharedData("course/example_textured.scene");
    REQUIRE_SHARED_DATA(wall);
    fs::create_directories(dir / "docs/accuracy");
    fs::create_directories(dir / "docs/sweeps");
    const std::map<fs::path, std::string> committed = {
        {dir / "docs/accuracy/accuracy.csv", "committed accuracy csv\n"},
        {dir / "docs/accuracy/accuracy.png", "committed accuracy chart"},
        {dir / "docs/sweeps/depth.csv", "committed depth csv\n"},
        {dir / "docs/sweeps/depth.png", "committed depth chart"}};
    for (const auto& [path, text] : committed) std::ofstream(path) << text;

    std::vector<fs::path> accuracyRuns;
    std::string accuracyOut;
    ASSERT_NO_FATAL_FAILURE(runTwice(dir, "accuracy --quick " + wall + chartFlag(),
                                     "facet-accuracy-", accuracyRuns, accuracyOut));
    for (const fs::path& run : accuracyRuns) {
        EXPECT_TRUE(fs::exists(run / "accuracy.csv")) << run;
        if (haveGnuplot()) {
            EXPECT_TRUE(isPng(run / "accuracy.png")) << run;
        }
        // The folder is named on stdout with the files in it.
        EXPECT_NE(accuracyOut.find((run.filename() / "accuracy.csv").string()), std::string::npos);
    }

    const std::string sweeps = "sweeps --quick --only depth" + chartFlag();
    std::vector<fs::path> sweepRuns;
    std::string sweepsOut;
    ASSERT_NO_FATAL_FAILURE(runTwice(dir, sweeps, "facet-sweeps-", sweepRuns, sweepsOut));
    for (const fs::path& run : sweepRuns) EXPECT_TRUE(fs::exists(run / "depth.csv")) << run;

    for (const auto& [path, text] : committed) EXPECT_EQ(readFile(path), text) << path;
    // Named explicitly, a folder is written (and made with its parents).
    const Outcome named = runIn(dir, sweeps + " -o runs/mine");
    ASSERT_EQ(named.exitCode, 0) << named.out;
    EXPECT_TRUE(fs::exists(dir / "runs/mine/depth.csv"));
    REQUIRE_GNUPLOT();
}

// --quick runs every phase of `accuracy` in seconds and says so through each: the ground
// truth's progress, the timing rounds, every method measured; the CSV says it was quick, the
// machine's load, and which methods the truth could not judge.
TEST_F(AccuracyCli, AccuracyQuickShowsProgressThroughEveryPhase) {
    const std::string course = facet::test::sharedData("course/");
    REQUIRE_SHARED_DATA(course + "brick.jpg");
    const Outcome r = runIn(dir, "accuracy --quick " + course + "example0.scene " + course +
                                     "example_textured.scene --texture " + course +
                                     "brick.jpg -o out" + chartFlag());
    ASSERT_EQ(r.exitCode, 0) << r.out;
    for (const char* line :
         {"accuracy: 2 scenes, 21 methods against a 2x2-sample truth",
          "accuracy: not measured: 2x2, 4x4, msaa4, msaa8",
          "[scene 1/2] example0: ground truth 128x128 at 2x2 samples:   0 %",
          "[scene 1/2] example0: ground truth 128x128 at 2x2 samples:  50 %",
          "[scene 1/2] example0: ground truth 128x128 at 2x2 samples: 100 %",
          "[scene 1/2] example0: ground truth 128x128 at 2x2 samples in ",
          "[scene 1/2] example0: timing, timed round 1/1, method 1/9 affine",
          "[9/21] example0 samples msaa2: ",
          "[scene 2/2] example_textured: ground truth 128x128 at 2x2 samples:  90 %",
          "[scene 2/2] example_textured: timing, timed round 1/1, method 1/12 affine",
          "[21/21] example_textured samples msaa2: ", "accuracy: done in "})
        EXPECT_NE(r.out.find(line), std::string::npos) << "missing: " << line << "\n" << r.out;
    const Csv csv = readCsv(dir / "out/accuracy.csv");
    ASSERT_EQ(csv.rows.size(), 22u);  // header + 9 + 12 methods
    EXPECT_EQ(csv.rows[0].back(), "pareto");
    const std::string notes = [&] {
        std::string all;
        for (const std::string& c : csv.commentText) all += c + "\n";
        return all;
    }();
    EXPECT_NE(notes.find("# load average at start: "), std::string::npos) << notes;
    EXPECT_NE(notes.find("--quick"), std::string::npos) << notes;
    EXPECT_NE(notes.find("# not measured (as many samples per pixel as the truth or more): 2x2, "
                         "4x4, msaa4, msaa8"),
              std::string::npos)
        << notes;
    int front = 0;
    for (std::size_t k = 1; k < csv.rows.size(); ++k) {
        ASSERT_EQ(csv.rows[k].size(), 15u) << k;
        EXPECT_EQ(csv.rows[k][3], "128");  // quick: at most 128 px wide
        front += csv.rows[k][14] == "1";
    }
    EXPECT_GE(front, 2) << "each scene's fastest method is on its front";
    if (haveGnuplot()) {
        EXPECT_TRUE(isPng(dir / "out/accuracy.png"));
    }
    REQUIRE_GNUPLOT();
}

// --quick runs every sweep in seconds, and each sweep's progress reaches a log.
TEST_F(AccuracyCli, SweepsQuickRunsEverySweepWithProgress) {
    // The subpixel and camera_paths sweeps draw the shared bunny and Spot.
    REQUIRE_SHARED_DATA(facet::test::sharedData("scenes/bunny_1280x720.scene"));
    REQUIRE_SHARED_DATA(facet::test::sharedData("scenes/spot_1280x720.scene"));
    const Outcome r = runIn(dir, "sweeps --quick -o out" + chartFlag());
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("sweeps: 6 sweeps (quick), writing to out"), std::string::npos) << r.out;
    const char* names[] = {"view_angle", "highlights", "depth",
                           "subpixel",   "extreme",    "camera_paths"};
    for (int k = 0; k < 6; ++k) {
        const std::string n = std::to_string(k + 1);
        EXPECT_NE(r.out.find("[" + n + "/6] step 1 ("), std::string::npos) << n << "\n" << r.out;
        EXPECT_NE(r.out.find("[" + n + "/6] " + names[k] + ": "), std::string::npos) << n << "\n"
                                                                                     << r.out;
        const Csv csv = readCsv(dir / "out" / (std::string(names[k]) + ".csv"));
        EXPECT_EQ(csv.comments, 3) << names[k];
        EXPECT_GE(csv.rows.size(), 2u) << names[k];
        if (haveGnuplot()) {
            EXPECT_TRUE(isPng(dir / "out" / (std::string(names[k]) + ".png")));
        }
    }
    REQUIRE_GNUPLOT();
}

// The bug: accuracy read every file as a .scene, so a mesh's first line was taken for a mesh
// file name ("must end in .off or .obj"). A bare mesh opens as `facet render` opens it.
TEST_F(AccuracyCli, AccuracyOpensABareMesh) {
    const std::string teapot = facet::test::sharedData("models/teapot.obj");
    REQUIRE_SHARED_DATA(teapot);
    const Outcome r = runIn(dir, "accuracy --quick --no-chart " + teapot + " -o out");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_EQ(r.out.find("must end in"), std::string::npos) << r.out;
    const Csv csv = readCsv(dir / "out/accuracy.csv");
    ASSERT_GE(csv.rows.size(), 2u);
    for (std::size_t k = 1; k < csv.rows.size(); ++k) {
        EXPECT_EQ(csv.rows[k][0], "teapot");
        EXPECT_EQ(csv.rows[k][3], "128");  // 1280×720 (spec §3b), at most 128 wide with --quick
        EXPECT_EQ(csv.rows[k][4], "72");
    }
}

// With a 2x2 truth the CLI once ranked 2x2 and 4x4 "better" than the methods the truth can
// judge. Now it measures what the viewer measures for the same scene and truth: the methods
// below the truth, by the one rule both call.
TEST_F(AccuracyCli, CliAndViewerMeasureTheSameMethodsCoarserThanTheTruth) {
    const std::string teapot = facet::test::sharedData("models/teapot.obj");
    REQUIRE_SHARED_DATA(teapot);
    Result<facet::Scene> opened = facet::openSceneFile(teapot);
    ASSERT_TRUE(opened.ok());
    facet::Scene scene = std::move(opened).value();
    scene.camera = facet::resizedCamera(scene.camera, 128, 72);
    for (const int samples : {2, 3, 4}) {
        SCOPED_TRACE(samples);
        const std::string out = "out" + std::to_string(samples);
        const Outcome r = runIn(dir, "accuracy --quick --no-chart --samples " +
                                         std::to_string(samples) + " " + teapot + " -o " + out);
        ASSERT_EQ(r.exitCode, 0) << r.out;
        const std::vector<std::string> cli = methodsIn(readCsv(dir / out / "accuracy.csv"));

        facet::view::AccuracyJob job;
        ASSERT_TRUE(job.start(scene, 1, facet::app::baseSettings(scene), samples, 1, 0));
        job.wait();
        const std::shared_ptr<const facet::view::AccuracyReport> report = job.report();
        ASSERT_TRUE(report) << job.status().message;
        std::vector<std::string> viewer;
        for (const facet::view::AccuracyRow& row : report->rows) viewer.push_back(row.method);
        EXPECT_EQ(cli, viewer);

        // Every one measured is coarser than the truth; every one left out is not.
        for (const facet::app::AccuracyMethod& m : facet::app::accuracyMethods(scene)) {
            const int perPixel = std::max(1, m.settings.supersample) *
                                 std::max(1, m.settings.supersample) * std::max(1, m.settings.msaa);
            const bool measured = std::find(cli.begin(), cli.end(), m.name) != cli.end();
            EXPECT_EQ(measured, perPixel < samples * samples) << m.name;
            if (!measured) {
                EXPECT_NE(r.out.find("not measured: "), std::string::npos) << r.out;
            }
        }
        if (samples == 2) {
            EXPECT_EQ(report->leftOut, "2x2, 4x4, msaa4, msaa8");
            EXPECT_NE(r.out.find("not measured: 2x2, 4x4, msaa4, msaa8"), std::string::npos);
        }
    }
}

// A full-size run of one scene: one CSV row per method the 4x4 truth can judge (5
// interpolations, 3 filters, 2 lightings, 1x1, 2x2 and msaa2/4/8: 4x4 left out), perspective no
// worse than affine, and more samples no worse than one.
TEST_F(AccuracyCli, AccuracyWritesOneRowPerMethodAndPerspectiveBeatsAffine) {
    const std::string course = facet::test::sharedData("course/");
    REQUIRE_SHARED_DATA(course + "brick.jpg");
    const Outcome r =
        runIn(dir, "accuracy " + course + "example_textured.scene --texture " + course +
                       "brick.jpg --samples 4 --frames 1 --warmup 0 --no-chart -o a");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("[15/15] example_textured samples msaa8:"), std::string::npos) << r.out;
    const Csv csv = readCsv(dir / "a/accuracy.csv");
    EXPECT_GE(csv.comments, 3);
    ASSERT_EQ(csv.rows.size(), 16u);  // header + 15 methods
    ASSERT_EQ(csv.rows[0].size(), 15u);
    EXPECT_EQ(csv.rows[0][9], "rmse");
    std::map<std::string, double> rmse;
    for (std::size_t k = 1; k < csv.rows.size(); ++k) {
        ASSERT_EQ(csv.rows[k].size(), 15u) << k;
        EXPECT_EQ(csv.rows[k][0], "example_textured");
        EXPECT_EQ(csv.rows[k][3], "512");
        EXPECT_GT(std::stod(csv.rows[k][6]), 0.0);  // median ms
        rmse[csv.rows[k][2]] = std::stod(csv.rows[k][9]);
    }
    EXPECT_EQ(rmse.count("4x4"), 0u);
    for (const char* m : {"affine", "perspective", "1x1", "2x2", "msaa4"})
        ASSERT_EQ(rmse.count(m), 1u) << m;
    EXPECT_LE(rmse["perspective"], rmse["affine"]);
    EXPECT_LT(rmse["2x2"], rmse["1x1"]);
    EXPECT_LT(rmse["msaa4"], rmse["1x1"]);
}

// An output folder that cannot be made is bad input, refused before anything is measured.
// (The other refusals: cli_test's AccuracyBadInputIsOneLine and SweepsBadInputIsOneLine.)
TEST_F(AccuracyCli, AnOutputFolderThatCannotBeMadeIsOneLine) {
    std::ofstream(dir / "a_file") << "not a folder";
    for (const std::string& args :
         {std::string("accuracy --no-chart ") + FACET_ASSETS_DIR + "/default.scene -o a_file",
          std::string("accuracy --no-chart ") + FACET_ASSETS_DIR +
              "/default.scene -o /proc/facet_no_such/dir",
          std::string("sweeps --no-chart -o a_file")}) {
        const Outcome r = runIn(dir, args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.out;
        EXPECT_EQ(countLines(r.out), 1) << args << "\n" << r.out;
        EXPECT_NE(r.out.find("cannot create the output folder"), std::string::npos) << r.out;
    }
    EXPECT_TRUE(foldersStartingWith(dir, "facet-").empty());
}

// The folder rule and the progress display themselves.
TEST(RunOutput, NewFoldersNeverCollideAndNamedOnesAreMade) {
    const fs::path dir =
        fs::temp_directory_path() / ("facet_run_output_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::set<std::string> made;
    for (int k = 0; k < 3; ++k) {
        const Result<std::string> f = facet::app::prepareOutputFolder("", "facet-x", dir.string());
        ASSERT_TRUE(f.ok()) << f.error().what();
        EXPECT_TRUE(fs::is_directory(f.value()));
        EXPECT_TRUE(made.insert(f.value()).second) << f.value() << " made twice";
    }
    const std::string named = (dir / "a/b").string();
    const Result<std::string> n = facet::app::prepareOutputFolder(named, "facet-x", dir.string());
    ASSERT_TRUE(n.ok());
    EXPECT_EQ(n.value(), named);
    EXPECT_TRUE(fs::is_directory(named));
    std::ofstream(dir / "file") << "x";
    const Result<std::string> bad =
        facet::app::prepareOutputFolder((dir / "file").string(), "facet-x");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().what().find("file"), std::string::npos);
    fs::remove_all(dir);
}

TEST(RunOutput, ALogGetsForcedLinesAndOneEveryFewSeconds) {
    std::FILE* log = std::tmpfile();
    ASSERT_NE(log, nullptr);
    {
        facet::app::ProgressLine progress(log, 0.2);
        EXPECT_FALSE(progress.interactive());
        progress.update("first");         // the first line always
        progress.update("too soon");      // within 0.2 s: skipped
        progress.update("forced", true);  // a phase starting
        std::this_thread::sleep_for(std::chrono::milliseconds(250));
        progress.update("later");  // 0.2 s on
        progress.finish("result");
    }
    std::rewind(log);
    std::string text;
    for (int c; (c = std::fgetc(log)) != EOF;) text += static_cast<char>(c);
    std::fclose(log);
    EXPECT_EQ(text, "first\nforced\nlater\nresult\n");
}

}  // namespace
