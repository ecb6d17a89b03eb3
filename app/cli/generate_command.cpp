// `facet generate`: writes procedural meshes as .off, e.g. the default scene's torus knot.

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "exit_code.hpp"
#include "facet/mesh_io.hpp"
#include "facet/procedural.hpp"
#include "generate_command.hpp"

namespace facet::app {
namespace {

struct GenerateOptions {
    std::string kind;
    std::string output;
    int detail = 0;  // 0: the kind's default
};

int runGenerate(const GenerateOptions& o) {
    Mesh mesh;
    if (o.kind == "knot") {
        const int n = o.detail > 0 ? o.detail : 240;
        mesh = makeTorusKnot(2, 3, n, std::max(8, n / 10));
    } else if (o.kind == "sphere") {
        const int n = o.detail > 0 ? o.detail : 32;
        mesh = makeUvSphere(n, 2 * n);
    } else {
        const int n = o.detail > 0 ? o.detail : 16;
        mesh = makeJitteredGrid(n, n, 0.3f, 1234u);
    }
    if (Status st = writeOff(mesh, o.output); !st) {
        std::fprintf(stderr, "facet generate: %s\n", st.error().what().c_str());
        return kFailed;
    }
    std::printf("wrote %s (%zu vertices, %zu triangles)\n", o.output.c_str(), mesh.vertexCount(),
                mesh.triangleCount());
    return kOk;
}

}  // namespace

void addGenerateCommand(CLI::App& app, int& exitCode) {
    auto opts = std::make_shared<GenerateOptions>();
    CLI::App* cmd = app.add_subcommand("generate", "Write a procedural mesh as .off");
    cmd->add_option("kind", opts->kind,
                    "knot (torus knot), sphere (UV sphere) or grid (jittered plane)")
        ->required()
        ->check(CLI::IsMember({"knot", "sphere", "grid"}));
    cmd->add_option("-o,--output", opts->output, "Output .off path")->required();
    cmd->add_option("--detail", opts->detail, "Resolution (segments, rings or cells)")
        ->check(CLI::Range(1, 4096));
    cmd->callback([opts, &exitCode] { exitCode = runGenerate(*opts); });
}

}  // namespace facet::app
