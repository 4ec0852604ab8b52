#pragma once
// Runs a GLSL ES 3.00 function `float NAME(vec3)` for real on Mesa's software
// rasterizer llvmpipe: a headless EGL display (EGL_PLATFORM_SURFACELESS_MESA), an
// OpenGL ES 3.0 context made current without a surface (EGL_KHR_surfaceless_context),
// the points in an N×1 RGBA32F texture read with texelFetch, one full-screen
// triangle into an N×1 framebuffer, the values read back bit-exactly.
//
// The colour attachment is GL_R32UI and the shader writes floatBitsToUint(value):
// integer formats are colour-renderable in core ES 3.0, so no extension
// (EXT_color_buffer_float) is needed and the float crosses unchanged.
//
// Compiled only where CMake found EGL and GLESv2 (IMPLICITIZER_HAVE_EGL); elsewhere
// GlesRunner::instance() reports why it is unavailable and the tests skip.

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#if defined(IMPLICITIZER_HAVE_EGL)
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>
#endif

namespace implicitizer::testing {

class GlesRunner {
 public:
  // The process's runner, created on first use. unavailable() says why it cannot
  // run shaders ("" when it can).
  static GlesRunner& instance() {
    static GlesRunner runner;
    return runner;
  }

  const std::string& unavailable() const { return unavailable_; }
  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  const std::string& renderer() const { return renderer_; }

  // Evaluates `function` (GLSL defining `float name(vec3 p)`) at the points
  // (x, y, z per point). On failure returns {} and sets `error`.
  std::vector<float> evaluate(const std::string& function, const std::string& name, const std::vector<float>& xyz,
                              std::string& error);

  GlesRunner(const GlesRunner&) = delete;
  GlesRunner& operator=(const GlesRunner&) = delete;

 private:
  GlesRunner();
  ~GlesRunner();

  std::string unavailable_ = "not initialised";
  std::string renderer_;
#if defined(IMPLICITIZER_HAVE_EGL)
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
#endif
};

#if defined(IMPLICITIZER_HAVE_EGL)

namespace gles_detail {

inline std::string shader_log(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  glGetShaderInfoLog(shader, length, nullptr, log.data());
  return log;
}

inline std::string program_log(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  glGetProgramInfoLog(program, length, nullptr, log.data());
  return log;
}

inline GLuint compile(GLenum kind, const std::string& source, std::string& error) {
  const GLuint shader = glCreateShader(kind);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    error = "shader does not compile: " + shader_log(shader);
    glDeleteShader(shader);
    return 0;
  }
  return shader;
}

}  // namespace gles_detail

inline GlesRunner::GlesRunner() {
  // Mesa: never a hardware driver, always llvmpipe (read at eglInitialize).
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  const std::string extensions = client != nullptr ? client : "";
  if (extensions.find("EGL_MESA_platform_surfaceless") == std::string::npos) {
    unavailable_ = "EGL has no EGL_MESA_platform_surfaceless (client extensions: " + extensions + ")";
    return;
  }
  const auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (get_platform_display == nullptr) {
    unavailable_ = "EGL has no eglGetPlatformDisplayEXT";
    return;
  }
  display_ = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  EGLint major = 0, minor = 0;
  if (display_ == EGL_NO_DISPLAY || eglInitialize(display_, &major, &minor) != EGL_TRUE) {
    unavailable_ = "eglInitialize of the surfaceless platform failed (is libgl1-mesa-dri installed?)";
    display_ = EGL_NO_DISPLAY;
    return;
  }
  const char* display_extensions = eglQueryString(display_, EGL_EXTENSIONS);
  if (display_extensions == nullptr ||
      std::string(display_extensions).find("EGL_KHR_surfaceless_context") == std::string::npos) {
    unavailable_ = "EGL display has no EGL_KHR_surfaceless_context";
    return;
  }
  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                                      EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  if (eglChooseConfig(display_, config_attributes, &config, 1, &configs) != EGL_TRUE || configs < 1) {
    // Some surfaceless drivers list configs without surface types: ask for ES 3 only.
    const EGLint es3_only[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_NONE};
    if (eglChooseConfig(display_, es3_only, &config, 1, &configs) != EGL_TRUE || configs < 1) {
      unavailable_ = "no EGL config with EGL_OPENGL_ES3_BIT";
      return;
    }
  }
  if (eglBindAPI(EGL_OPENGL_ES_API) != EGL_TRUE) {
    unavailable_ = "eglBindAPI(EGL_OPENGL_ES_API) failed";
    return;
  }
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
  context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, context_attributes);
  if (context_ == EGL_NO_CONTEXT) {
    unavailable_ = "eglCreateContext (OpenGL ES 3.0) failed";
    return;
  }
  if (eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) != EGL_TRUE) {
    unavailable_ = "eglMakeCurrent without a surface failed";
    return;
  }
  const GLubyte* renderer = glGetString(GL_RENDERER);
  renderer_ = renderer != nullptr ? reinterpret_cast<const char*>(renderer) : "";
  if (renderer_.find("llvmpipe") == std::string::npos) {
    unavailable_ = "the renderer is not llvmpipe: '" + renderer_ + "'";
    return;
  }
  unavailable_.clear();
}

inline GlesRunner::~GlesRunner() {
  if (display_ == EGL_NO_DISPLAY) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

inline std::vector<float> GlesRunner::evaluate(const std::string& function, const std::string& name,
                                               const std::vector<float>& xyz, std::string& error) {
  using namespace gles_detail;
  if (!unavailable_.empty()) {
    error = unavailable_;
    return {};
  }
  const GLsizei n = static_cast<GLsizei>(xyz.size() / 3);
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (n < 1 || n > max_size) {
    error = "point count " + std::to_string(n) + " outside [1, GL_MAX_TEXTURE_SIZE = " + std::to_string(max_size) + "]";
    return {};
  }

  const std::string vertex =
      "#version 300 es\n"
      "void main() {\n"
      "  // One triangle covering the viewport: (-1,-1), (3,-1), (-1,3).\n"
      "  vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);\n"
      "  gl_Position = vec4(p, 0.0, 1.0);\n"
      "}\n";
  const std::string fragment = "#version 300 es\nprecision highp float;\nprecision highp int;\n" + function +
                               "\nuniform highp sampler2D points;\n"
                               "layout(location = 0) out highp uint result;\n"
                               "void main() {\n"
                               "  vec3 p = texelFetch(points, ivec2(int(gl_FragCoord.x), 0), 0).xyz;\n"
                               "  result = floatBitsToUint(" +
                               name + "(p));\n}\n";
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex, error);
  if (vs == 0) return {};
  const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment, error);
  if (fs == 0) {
    glDeleteShader(vs);
    return {};
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint linked = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  if (linked != GL_TRUE) {
    error = "program does not link: " + program_log(program);
    glDeleteProgram(program);
    return {};
  }

  // The points: texel i = (x, y, z, 0). RGBA32F is not filterable, hence NEAREST.
  std::vector<float> texels(static_cast<std::size_t>(n) * 4, 0.0f);
  for (GLsizei i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      texels[static_cast<std::size_t>(i) * 4 + k] = xyz[static_cast<std::size_t>(i) * 3 + k];
    }
  }
  GLuint points = 0, target = 0, framebuffer = 0, vertex_array = 0;
  glGenTextures(1, &points);
  glBindTexture(GL_TEXTURE_2D, points);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, n, 1, 0, GL_RGBA, GL_FLOAT, texels.data());

  glGenTextures(1, &target);
  glBindTexture(GL_TEXTURE_2D, target);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R32UI, n, 1, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);

  std::vector<float> values;
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    error = "the R32UI framebuffer is not complete";
  } else {
    glGenVertexArrays(1, &vertex_array);
    glBindVertexArray(vertex_array);
    glViewport(0, 0, n, 1);
    glDisable(GL_DITHER);
    glUseProgram(program);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, points);
    glUniform1i(glGetUniformLocation(program, "points"), 0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    // The one combination ES 3.0 guarantees for integer attachments: RGBA_INTEGER, UNSIGNED_INT.
    std::vector<std::uint32_t> pixels(static_cast<std::size_t>(n) * 4, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, n, 1, GL_RGBA_INTEGER, GL_UNSIGNED_INT, pixels.data());
    const GLenum status = glGetError();
    if (status != GL_NO_ERROR) {
      error = "GL error " + std::to_string(status);
    } else {
      values.resize(static_cast<std::size_t>(n));
      for (GLsizei i = 0; i < n; ++i) {
        const std::uint32_t bits = pixels[static_cast<std::size_t>(i) * 4];
        float value;
        static_assert(sizeof(value) == sizeof(bits));
        std::memcpy(&value, &bits, sizeof(value));
        values[static_cast<std::size_t>(i)] = value;
      }
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteTextures(1, &target);
  glDeleteTextures(1, &points);
  if (vertex_array != 0) glDeleteVertexArrays(1, &vertex_array);
  glDeleteProgram(program);
  return values;
}

#else  // !IMPLICITIZER_HAVE_EGL

inline GlesRunner::GlesRunner()
    : unavailable_("built without EGL/GLESv2 (install libegl-dev libgles-dev libgl1-mesa-dri and reconfigure)") {}
inline GlesRunner::~GlesRunner() = default;
inline std::vector<float> GlesRunner::evaluate(const std::string&, const std::string&, const std::vector<float>&,
                                               std::string& error) {
  error = unavailable_;
  return {};
}

#endif

}  // namespace implicitizer::testing
