#include "gl_program.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>
#include <vector>

#ifndef FACET_SHADERS_DIR
#define FACET_SHADERS_DIR ""
#endif

namespace facet::gl {
namespace {

namespace fs = std::filesystem;

Error shaderError(const std::string& where, const std::string& message) {
    return Error{{where, 0}, message};
}

/// The first folder holding twin.vert: the compiled-in one, then shaders/ beside the
/// executable or in its parents (a build folder copied elsewhere keeps working).
std::string findShaderFolder() {
    std::error_code ec;
    const fs::path compiled(FACET_SHADERS_DIR);
    if (!compiled.empty() && fs::exists(compiled / "twin.vert", ec)) return compiled.string();
    fs::path dir = fs::read_symlink("/proc/self/exe", ec).parent_path();
    for (int up = 0; !ec && up < 4 && !dir.empty(); ++up, dir = dir.parent_path()) {
        if (fs::exists(dir / "shaders" / "twin.vert", ec)) return (dir / "shaders").string();
        if (dir == dir.parent_path()) break;
    }
    return {};
}

bool readFile(const fs::path& path, std::string& text) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream s;
    s << in.rdbuf();
    text = s.str();
    return true;
}

/// One stage's source: the file's #version line, the variant's defines, the lighting
/// functions, then the rest of the file. #line keeps the driver's line numbers those of the
/// files (source string 1 is the lighting file, 0 the stage's own).
std::string assemble(const std::string& stage, const std::string& defines,
                     const std::string& lighting) {
    const std::size_t eol = stage.find('\n');
    const std::string version = stage.substr(0, eol + 1);
    const std::string body = eol == std::string::npos ? std::string() : stage.substr(eol + 1);
    return version + defines + "#line 1 1\n" + lighting + "\n#line 2 0\n" + body;
}

std::string infoLog(GLuint object, bool program) {
    GLint length = 0;
    if (program)
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length > 1 ? length : 1), '\0');
    if (program)
        glGetProgramInfoLog(object, static_cast<GLsizei>(log.size()), nullptr, log.data());
    else
        glGetShaderInfoLog(object, static_cast<GLsizei>(log.size()), nullptr, log.data());
    return log.data();
}

/// Compiles one stage; 0 and `log` filled on failure.
GLuint compile(GLenum kind, const std::string& source, std::string& log) {
    const GLuint shader = glCreateShader(kind);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok == GL_TRUE) return shader;
    log = infoLog(shader, false);
    glDeleteShader(shader);
    return 0;
}

}  // namespace

Result<ShaderSources> loadShaderSources() {
    ShaderSources s;
    s.folder = findShaderFolder();
    if (s.folder.empty())
        return shaderError("twin.vert", "the OpenGL twin's shaders were not found (looked in " +
                                            std::string(FACET_SHADERS_DIR) +
                                            " and in shaders/ beside the executable)");
    const fs::path dir(s.folder);
    for (const auto& [name, text] : {std::pair<const char*, std::string*>{"twin.vert", &s.vertex},
                                     {"twin.frag", &s.fragment},
                                     {"twin_lighting.glsl", &s.lighting}}) {
        if (!readFile(dir / name, *text))
            return shaderError((dir / name).string(), "cannot read the shader");
    }
    return s;
}

Result<Program> buildProgram(const ShaderSources& sources, const std::string& defines) {
    std::string log;
    const GLuint vs =
        compile(GL_VERTEX_SHADER, assemble(sources.vertex, defines, sources.lighting), log);
    if (vs == 0) return shaderError(sources.folder + "/twin.vert", log + "variant:\n" + defines);
    const GLuint fs =
        compile(GL_FRAGMENT_SHADER, assemble(sources.fragment, defines, sources.lighting), log);
    if (fs == 0) {
        glDeleteShader(vs);
        return shaderError(sources.folder + "/twin.frag", log + "variant:\n" + defines);
    }
    Program program(glCreateProgram());
    glAttachShader(program.get(), vs);
    glAttachShader(program.get(), fs);
    glLinkProgram(program.get());
    glDeleteShader(vs);  // only flagged: the program keeps them until it goes
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE)
        return shaderError(sources.folder,
                           "linking twin.vert + twin.frag failed: " + infoLog(program.get(), true) +
                               "variant:\n" + defines);
    return program;
}

}  // namespace facet::gl
