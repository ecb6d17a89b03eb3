// Example: build a mesh in code (a pyramid with a colour per corner), place a camera and a
// light, render it lit with Phong shading and write a PNG.
//
//   mesh_in_code out.png

#include <cstdio>
#include <memory>

#include "facet/image_io.hpp"
#include "facet/render.hpp"
#include "facet/scene.hpp"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUT.png\n", argv[0]);
        return 2;
    }
    // Four base corners and an apex; triangles counter-clockwise seen from outside.
    facet::Mesh mesh;
    mesh.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}, {0, 1.5f, 0}};
    mesh.colors = {
        {1, 0.3f, 0.2f}, {0.2f, 0.8f, 0.3f}, {0.2f, 0.4f, 1}, {1, 0.9f, 0.2f}, {1, 1, 1}};
    mesh.indices = {0, 4, 1, 1, 4, 2, 2, 4, 3, 3, 4, 0, 0, 1, 2, 0, 2, 3};

    facet::Scene scene;
    scene.mesh = std::make_shared<const facet::Mesh>(std::move(mesh));
    // The course's camera convention: the y hint points to image-down, so (0, -1, 0) shows +Y
    // up. The focal length is in pixels.
    scene.camera.eye = {3.0, 2.5, 4.0};
    scene.camera.look = {0.0, 0.5, 0.0};
    scene.camera.up = {0.0, -1.0, 0.0};
    scene.camera.focal = 700.0;
    scene.camera.width = 640;
    scene.camera.height = 480;
    scene.lighting.ambient = 0.3;
    scene.lighting.light.position = {4.0, 6.0, 3.0, 1.0};  // a point light (w = 1)
    scene.lighting.material = {.ka = 0.4, .kd = 0.8, .ks = 0.5, .s = 32.0};

    facet::RenderSettings settings;
    settings.lighting = facet::Lighting::Phong;
    settings.cullBackFaces = true;

    facet::Renderer renderer;
    facet::Framebuffer frame;
    if (auto stats = renderer.render(scene, settings, frame); !stats) {
        std::fprintf(stderr, "%s\n", stats.error().what().c_str());
        return 2;
    }
    if (facet::Status written = facet::writePng(frame, argv[1]); !written) {
        std::fprintf(stderr, "%s\n", written.error().what().c_str());
        return 1;
    }
    std::printf("wrote %s (%dx%d)\n", argv[1], frame.width, frame.height);
    return 0;
}
