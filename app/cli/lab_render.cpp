#include "lab_render.hpp"

#include <cstdio>

#include "exit_code.hpp"
#include "facet/image_io.hpp"
#include "lab/renderer.hpp"

namespace facet::app {

int renderLab(const Scene& scene, const RenderSettings& settings, const std::string& output) {
    lab::Renderer renderer;
    Framebuffer frame;
    const lab::Report report = renderer.render(scene, settings, frame);
    if (Status st = writePng(frame, output); !st) {
        std::fprintf(stderr, "facet render: %s\n", st.error().what().c_str());
        return kFailed;
    }
    std::printf("wrote %s (%dx%d, the lab's pipeline, %zu fragments)\n", output.c_str(),
                frame.width, frame.height, report.fragments);
    if (!report.notStarted.empty()) {
        std::printf("steps not started (still the stubs):");
        for (const lab::Step s : report.notStarted)
            std::printf(" %.*s", static_cast<int>(lab::stepName(s).size()),
                        lab::stepName(s).data());
        std::printf("\n");
    }
    if (const std::string d = lab::differences(settings); !d.empty())
        std::printf("lab pipeline: %s\n", d.c_str());
    return kOk;
}

}  // namespace facet::app
