#include "gl_program.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>
#include <utility>
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

/// The driver's log of a shader or program, without the trailing newline some drivers add.
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
    std::string text = log.data();
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    return text.empty() ? "(the driver gave no log)" : text;
}

/// `log`, then `note` on lines of its own when there is one.
std::string withNote(const std::string& log, const std::string& note) {
    return note.empty() ? log : log + "\n" + note;
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

/// One twin stage's source: the file's #version line, the variant's defines, the lighting
/// functions, then the rest of the file. #line keeps the driver's line numbers those of the
/// files (source string 1 is the lighting file, 0 the stage's own).
StageSource assemble(const StageSource& stage, const std::string& defines,
                     const std::string& lighting) {
    const std::size_t eol = stage.text.find('\n');
    const std::string version = stage.text.substr(0, eol + 1);
    const std::string body = eol == std::string::npos ? std::string() : stage.text.substr(eol + 1);
    return {stage.path, version + defines + "#line 1 1\n" + lighting + "\n#line 2 0\n" + body};
}

}  // namespace

Result<std::string> findShaderFolder(const std::string& file) {
    std::error_code ec;
    std::string looked;
    if (const char* env = std::getenv("FACET_SHADERS"); env != nullptr && *env != '\0') {
        // Asked for explicitly: no silent fallback to another folder's files.
        if (fs::exists(fs::path(env) / file, ec)) return std::string(env);
        return shaderError(file, std::string("not found in $FACET_SHADERS (") + env + ")");
    }
    const fs::path compiled(FACET_SHADERS_DIR);
    if (!compiled.empty() && fs::exists(compiled / file, ec)) return compiled.string();
    // /proc/self/exe: the executable wherever it was started from, so a copied build works.
    fs::path dir = fs::read_symlink("/proc/self/exe", ec).parent_path();
    for (int up = 0; !ec && up < 4 && !dir.empty(); ++up, dir = dir.parent_path()) {
        if (fs::exists(dir / "shaders" / file, ec)) return (dir / "shaders").string();
        if (dir == dir.parent_path()) break;
    }
    return shaderError(file, "the shaders were not found (looked in $FACET_SHADERS, " +
                                 compiled.string() + " and in shaders/ beside the executable)");
}

Result<StageSource> readShaderFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return shaderError(path, "cannot read the shader");
    std::ostringstream s;
    s << in.rdbuf();
    return StageSource{path, s.str()};
}

Result<Program> linkProgram(const StageSource& vertex, const StageSource& fragment,
                            const std::string& note) {
    std::string log;
    const GLuint vs = compile(GL_VERTEX_SHADER, vertex.text, log);
    if (vs == 0) return shaderError(vertex.path, withNote(log, note));
    const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment.text, log);
    if (fs == 0) {
        glDeleteShader(vs);
        return shaderError(fragment.path, withNote(log, note));
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
        return shaderError(vertex.path, "linking with " + fragment.path + " failed: " +
                                            withNote(infoLog(program.get(), true), note));
    return program;
}

Result<Program> loadProgram(const std::string& vertexFile, const std::string& fragmentFile) {
    const Result<std::string> folder = findShaderFolder(vertexFile);
    if (!folder) return folder.error();
    const Result<StageSource> vertex = readShaderFile(*folder + "/" + vertexFile);
    if (!vertex) return vertex.error();
    const Result<StageSource> fragment = readShaderFile(*folder + "/" + fragmentFile);
    if (!fragment) return fragment.error();
    return linkProgram(*vertex, *fragment);
}

Result<ShaderSources> loadShaderSources() {
    const Result<std::string> folder = findShaderFolder("twin.vert");
    if (!folder) return folder.error();
    ShaderSources s;
    s.folder = *folder;
    Result<StageSource> vertex = readShaderFile(s.folder + "/twin.vert");
    if (!vertex) return vertex.error();
    Result<StageSource> fragment = readShaderFile(s.folder + "/twin.frag");
    if (!fragment) return fragment.error();
    Result<StageSource> lighting = readShaderFile(s.folder + "/twin_lighting.glsl");
    if (!lighting) return lighting.error();
    s.vertex = std::move(vertex).value();
    s.fragment = std::move(fragment).value();
    s.lighting = std::move(lighting).value().text;
    return s;
}

Result<Program> buildProgram(const ShaderSources& sources, const std::string& defines) {
    return linkProgram(assemble(sources.vertex, defines, sources.lighting),
                       assemble(sources.fragment, defines, sources.lighting),
                       "variant:\n" + defines);
}

}  // namespace facet::gl
