#include "state_file.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace facet::view {
namespace {

std::string num(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string vec(const glm::dvec3& v) {
    return num(v.x) + " " + num(v.y) + " " + num(v.z);
}

}  // namespace

std::string stateText(const ViewerModel& m, long long frames) {
    const Camera& c = m.scene.camera;
    std::ostringstream s;
    s << "# facet-view state at exit\n";
    s << "scene " << m.scene.path << "\n";
    s << "frames " << frames << "\n";
    s << "moved " << (m.orbitMoved ? 1 : 0) << "\n";
    s << "yaw " << num(m.orbit.yaw) << "\n";
    s << "pitch " << num(m.orbit.pitch) << "\n";
    s << "distance " << num(m.orbit.distance) << "\n";
    s << "target " << vec(m.orbit.target) << "\n";
    s << "focal " << num(m.focal) << "\n";
    s << "eye " << vec(c.eye) << "\n";
    s << "look " << vec(c.look) << "\n";
    s << "up " << vec(c.up) << "\n";
    s << "size " << c.width << " " << c.height << "\n";
    s << "frame_focal " << num(c.focal) << "\n";
    const Light& l = m.scene.lighting.light;
    s << "light " << num(l.position.x) << " " << num(l.position.y) << " " << num(l.position.z)
      << " " << num(l.position.w) << "\n";
    s << "ambient " << num(m.scene.lighting.ambient) << "\n";
    s << "intensity " << num(l.intensity) << "\n";
    const Material& mat = m.scene.lighting.material;
    s << "material " << num(mat.ka) << " " << num(mat.kd) << " " << num(mat.ks) << " " << num(mat.s)
      << "\n";
    s << "mode " << toString(m.settings.mode) << "\n";
    s << "shader " << toString(m.settings.shader) << "\n";
    s << "interp " << toString(m.settings.interp) << "\n";
    s << "lighting " << toString(m.settings.lighting) << "\n";
    s << "subpixel_bits " << m.settings.subPixelBits << "\n";
    s << "supersample " << m.settings.supersample << "\n";
    s << "view " << toString(m.settings.view) << "\n";
    s << "msaa " << m.settings.msaa << "\n";
    s << "renderer " << toString(m.rendererChoice) << "\n";
    s << "unsaved " << (m.unsaved() ? 1 : 0) << "\n";
    return s.str();
}

std::map<std::string, std::string> parseState(const std::string& text) {
    std::map<std::string, std::string> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        const auto space = line.find(' ');
        if (space == std::string::npos)
            out[line] = "";
        else
            out[line.substr(0, space)] = line.substr(space + 1);
    }
    return out;
}

Status writeTextFile(const std::string& path, const std::string& text) {
    std::ofstream f(path, std::ios::binary);
    f << text;
    f.close();
    if (!f) return Error{{path, 0}, "cannot write (is the folder there and writable?)"};
    return {};
}

}  // namespace facet::view
