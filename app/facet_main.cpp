// The facet command-line tool: renders scenes to PNG and generates meshes.

#include <cstdio>
#include <cstdlib>
#include <string>

#include <unistd.h>

#include "commands.hpp"
#include "facet/version.hpp"

namespace {

/// libgomp's threads spin a long while at a barrier before they sleep (300000 turns by default).
/// On a shared machine the thread a barrier waits for is often descheduled, and the spinning
/// then holds the core it needs: the bunny at 720p on 2 threads took 210-250 ms per frame
/// instead of 86-99 ms with 10000 turns (load 17 on 2 cores, three interleaved runs each),
/// the same as sleeping at once (OMP_WAIT_POLICY=passive). 10000 turns (tens of µs) still
/// catch the quick hand-overs of an idle machine. libgomp reads it once, before main, so facet
/// restarts itself once with it set; a user's own setting is kept.
void useShortOpenMpSpins(char** argv) {
    if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr)
        return;
    if (setenv("GOMP_SPINCOUNT", "10000", 1) != 0) return;
    execv("/proc/self/exe", argv);  // returns only on failure: then run as we are
}

}  // namespace

int main(int argc, char** argv) {
    useShortOpenMpSpins(argv);
    CLI::App app{"facet: a software rasterizer. Renders .scene files (course format) to PNG."};
    app.require_subcommand(1);
    app.set_help_all_flag("--help-all", "Help for every sub-command");
    app.set_version_flag("--version", std::string("facet ") + facet::kVersionString,
                         "Print facet's version and exit");
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
    } catch (const CLI::CallForVersion& e) {
        std::printf("%s\n", e.what());
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
