// The facet command-line tool: renders scenes to PNG and generates meshes.

#include <cstdio>

#include "commands.hpp"

int main(int argc, char** argv) {
    CLI::App app{"facet: a software rasterizer. Renders .scene files (course format) to PNG."};
    app.require_subcommand(1);
    app.set_help_all_flag("--help-all", "Help for every sub-command");
    int exitCode = facet::app::kOk;
    facet::app::addRenderCommand(app, exitCode);
    facet::app::addGenerateCommand(app, exitCode);
    facet::app::addGlRenderCommand(app, exitCode);
    facet::app::addBenchCommand(app, exitCode);
    facet::app::addAccuracyCommand(app, exitCode);
    facet::app::addSweepsCommand(app, exitCode);
    facet::app::addInspectCommand(app, exitCode);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        std::fputs(app.help().c_str(), stdout);
        return facet::app::kOk;
    } catch (const CLI::CallForAllHelp&) {
        std::fputs(app.help("", CLI::AppFormatMode::All).c_str(), stdout);
        return facet::app::kOk;
    } catch (const CLI::ParseError& e) {
        // Help for a sub-command arrives as CallForHelp from the sub-command itself.
        if (e.get_exit_code() == 0) {
            for (const CLI::App* sub : app.get_subcommands())
                std::fputs(sub->help().c_str(), stdout);
            return facet::app::kOk;
        }
        std::fprintf(stderr, "facet: %s (see 'facet --help')\n", e.what());
        return facet::app::kBadInput;
    }
    return exitCode;
}
