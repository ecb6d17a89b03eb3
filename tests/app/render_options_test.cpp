// The option table the command line and the viewer share: both front ends offer every option of
// it with the same choices, and each choice sets the same RenderSettings in either. The CLI side
// is its own option code (render_options.cpp, compiled in), the viewer side parseOptions and the
// viewer's document, each on a real file.

#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <CLI/CLI.hpp>

#include "exit_code.hpp"
#include "options.hpp"
#include "render_option_table.hpp"
#include "render_options.hpp"
#include "run_process.hpp"
#include "viewer_model.hpp"

namespace {

using namespace facet;

const std::string kMesh = std::string(FACET_TEST_DATA) + "/obj_textured_quad.obj";

/// What the table's options decide in RenderSettings.
auto tableFields(const RenderSettings& s) {
    return std::tuple(s.mode, s.shader, s.interp, s.subdivision, s.lighting, s.filter, s.combine,
                      s.cullBackFaces, s.showNormals, s.view);
}

/// The settings `facet render MESH ARGS -o x.png` would draw with (nothing is written).
RenderSettings cliSettings(const std::vector<std::string>& args, int& code) {
    CLI::App cmd;
    app::RenderOptions o;
    app::addRenderOptions(cmd, o, "Interpolation", app::RenderCommand::engine);
    std::vector<const char*> argv{"facet render", kMesh.c_str(), "-o", "x.png"};
    for (const std::string& a : args) argv.push_back(a.c_str());
    cmd.parse(static_cast<int>(argv.size()), argv.data());
    Scene scene;
    RenderSettings settings;
    code = app::prepareRender(o, "facet render", scene, settings);
    return settings;
}

/// The settings facet-view MESH ARGS starts with.
RenderSettings viewerSettings(const std::vector<std::string>& args, std::string& error) {
    std::vector<const char*> argv{"facet-view", kMesh.c_str()};
    for (const std::string& a : args) argv.push_back(a.c_str());
    const view::ParsedOptions p = view::parseOptions(static_cast<int>(argv.size()), argv.data());
    view::ViewerModel m;
    if (p.exit) {
        error = p.text;
        return m.settings;
    }
    Status st = m.load(kMesh);
    if (st) st = app::applyRenderOptions(p.options, m.settings);
    if (!st) error = st.error().what();
    return m.settings;
}

TEST(RenderOptionTable, EveryChoiceSetsTheSameSettingsInTheCliAndTheViewer) {
    int compared = 0;
    for (const app::RenderOptionSpec& spec : app::renderOptionTable()) {
        std::vector<std::vector<std::string>> cases;
        if (std::holds_alternative<bool app::RenderOptionValues::*>(spec.field))
            cases.push_back({spec.name});  // a flag
        else if (spec.name != "--up")      // --up frames the mesh: no setting
            for (const std::string& choice : spec.choices) cases.push_back({spec.name, choice});
        if (spec.name == "--interp")
            for (const char* interp : {"affine", "subdivided", "subdivided:7"})
                cases.push_back({spec.name, interp});
        for (const std::vector<std::string>& args : cases) {
            int code = -1;
            const RenderSettings cli = cliSettings(args, code);
            std::string error;
            const RenderSettings viewer = viewerSettings(args, error);
            const std::string what = args.front() + " " + args.back();
            ASSERT_EQ(code, app::kOk) << what;
            ASSERT_EQ(error, "") << what;
            EXPECT_TRUE(tableFields(cli) == tableFields(viewer)) << what;
            ++compared;
        }
    }
    // The table is not empty, and a choice does change the settings (the check can fail).
    EXPECT_GT(compared, 20);
    int code = -1;
    EXPECT_FALSE(tableFields(cliSettings({"--shader", "depth"}, code)) ==
                 tableFields(cliSettings({"--shader", "painter"}, code)));
}

/// The part of a --help listing that describes `option`: from its name to the next option.
std::string entry(const std::string& help, const std::string& option) {
    const std::size_t at = help.find("\n  " + option + " ");
    if (at == std::string::npos) return {};
    return help.substr(at, help.find("\n  -", at + 1) - at);
}

TEST(RenderOptionTable, BothFrontEndsListEveryOptionWithTheTablesChoices) {
    const facet_test::Outcome cli =
        facet_test::runCommand(std::string(FACET_CLI) + " render --help");
    ASSERT_EQ(cli.exitCode, 0) << cli.out;
    const char* argv[] = {"facet-view", "--help"};
    const std::string viewer = view::parseOptions(2, argv).text;
    for (const app::RenderOptionSpec& spec : app::renderOptionTable()) {
        if (spec.name == "scene") continue;  // a positional, listed apart
        const std::string inCli = entry(cli.out, spec.name);
        const std::string inViewer = entry(viewer, spec.name);
        ASSERT_NE(inCli, "") << spec.name;
        ASSERT_NE(inViewer, "") << spec.name;
        for (const std::string& choice : spec.choices) {
            EXPECT_NE(inCli.find(choice), std::string::npos) << spec.name << " " << choice;
            EXPECT_NE(inViewer.find(choice), std::string::npos) << spec.name << " " << choice;
        }
    }
    // The debug views are documented where the help says.
    EXPECT_NE(entry(viewer, "--view").find("docs/debug-views.md"), std::string::npos);
}

TEST(RenderOptionTable, BadSizeInterpolationAndUpReadTheSameInBoth) {
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"--size", "0x10"}, {"--size", "big"}, {"--interp", "subdivided:1"}, {"--up", "w"}}) {
        int code = -1;
        testing::internal::CaptureStderr();
        cliSettings(args, code);
        const std::string cli = testing::internal::GetCapturedStderr();
        std::string viewer;
        viewerSettings(args, viewer);
        EXPECT_EQ(code, app::kBadInput) << args.back();
        ASSERT_EQ(cli.rfind("facet render: ", 0), 0u) << cli;
        ASSERT_EQ(viewer.rfind("facet-view: ", 0), 0u) << viewer;
        EXPECT_EQ(cli.substr(14), viewer.substr(12) + "\n");
    }
}

}  // namespace
