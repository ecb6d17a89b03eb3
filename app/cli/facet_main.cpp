// The facet command-line tool: renders scenes to PNG and generates meshes.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include <unistd.h>

#include "accuracy_command.hpp"
#include "bench_command.hpp"
#include "exit_code.hpp"
#include "facet/version.hpp"
#include "generate_command.hpp"
#include "gl_render_command.hpp"
#include "inspect_command.hpp"
#include "render_command.hpp"
#include "sweeps_command.hpp"

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

/// Levenshtein distance: insertions, deletions and substitutions of one character each.
std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = up;
        }
    }
    return row[b.size()];
}

/// The candidate closest to `word`, if it is close enough to be a typo of it (a third of its
/// letters at most, and at least one); empty otherwise.
std::string closest(std::string_view word, const std::vector<std::string>& candidates) {
    std::string best;
    std::size_t bestDistance = std::max<std::size_t>(1, word.size() / 3) + 1;
    for (const std::string& c : candidates) {
        const std::size_t d = editDistance(word, c);
        if (d < bestDistance) {
            bestDistance = d;
            best = c;
        }
    }
    return best;
}

/// "did you mean" for the first misspelt sub-command or option on the command line, or empty.
std::string suggestion(CLI::App& app, int argc, char** argv) {
    std::vector<std::string> commands;
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
        commands.push_back(sub->get_name());
    const CLI::App* command = nullptr;
    int at = 1;
    for (; at < argc; ++at) {
        const std::string_view arg = argv[at];
        if (arg.starts_with("-")) continue;
        for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
            if (sub->get_name() == arg) command = sub;
        if (command) break;
        const std::string guess = closest(arg, commands);
        if (!guess.empty())
            return "unknown command '" + std::string(arg) + "': did you mean '" + guess + "'?";
        std::string list;
        for (const std::string& c : commands) list += (list.empty() ? "" : ", ") + c;
        return "unknown command '" + std::string(arg) + "' (the commands: " + list + ")";
    }
    if (!command) return "";
    std::vector<std::string> options;
    for (const CLI::Option* option : command->get_options())
        for (const std::string& name : option->get_lnames()) options.push_back("--" + name);
    for (int i = at + 1; i < argc; ++i) {
        std::string_view arg = argv[i];
        if (!arg.starts_with("--")) continue;
        arg = arg.substr(0, arg.find('='));
        if (command->get_option_no_throw(std::string(arg)) != nullptr) continue;
        const std::string guess = closest(arg, options);
        if (!guess.empty())
            return "unknown option '" + std::string(arg) + "' for '" + command->get_name() +
                   "': did you mean '" + guess + "'?";
    }
    return "";
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
        if (const std::string hint = suggestion(app, argc, argv); !hint.empty())
            std::fprintf(stderr, "facet: %s (see 'facet --help')\n", hint.c_str());
        else
            std::fprintf(stderr, "facet: %s (see 'facet --help')\n", e.what());
        return facet::app::kBadInput;
    }
    return exitCode;
}
