#include "implicitizer/sdf/glsl_name.hpp"

#include <algorithm>
#include <string>

#include "implicitizer/core/errors.hpp"

namespace implicitizer {
namespace {

// Keywords and reserved words of GLSL ES 3.00 (section 3.7 and 3.8) and GLSL 3.30
// (section 3.6), merged; type names included. Sorted for binary search.
constexpr std::string_view kReserved[] = {
    "active", "asm", "atomic_uint", "attribute", "bool", "break", "buffer", "bvec2", "bvec3", "bvec4", "case",
    "cast", "centroid", "class", "coherent", "common", "const", "continue", "default", "discard", "dmat2",
    "dmat2x2", "dmat2x3", "dmat2x4", "dmat3", "dmat3x2", "dmat3x3", "dmat3x4", "dmat4", "dmat4x2", "dmat4x3",
    "dmat4x4", "do", "double", "dvec2", "dvec3", "dvec4", "else", "enum", "extern", "external", "false", "filter",
    "fixed", "flat", "float", "for", "fvec2", "fvec3", "fvec4", "goto", "half", "highp", "hvec2", "hvec3",
    "hvec4", "if", "iimage1D", "iimage2D", "iimage3D", "image1D", "image2D", "image3D", "in", "inline", "inout",
    "input", "int", "interface", "invariant", "isampler1D", "isampler2D", "isampler2DArray", "isampler3D",
    "isamplerCube", "layout", "long", "lowp", "mat2", "mat2x2", "mat2x3", "mat2x4", "mat3", "mat3x2", "mat3x3",
    "mat3x4", "mat4", "mat4x2", "mat4x3", "mat4x4", "mediump", "namespace", "noinline", "noperspective", "out",
    "output", "packed", "partition", "patch", "precise", "precision", "public", "readonly", "resource",
    "restrict", "return", "row_major", "sample", "sampler1D", "sampler1DArray", "sampler1DShadow", "sampler2D",
    "sampler2DArray", "sampler2DArrayShadow", "sampler2DMS", "sampler2DRect", "sampler2DShadow", "sampler3D",
    "sampler3DRect", "samplerBuffer", "samplerCube", "samplerCubeShadow", "shared", "short", "sizeof", "smooth",
    "static", "struct", "subroutine", "superp", "switch", "template", "this", "true", "typedef", "uimage1D",
    "uimage2D", "uimage3D", "uint", "uniform", "union", "unsigned", "usampler1D", "usampler2D",
    "usampler2DArray", "usampler3D", "usamplerCube", "using", "uvec2", "uvec3", "uvec4", "varying", "vec2",
    "vec3", "vec4", "void", "volatile", "while", "writeonly"};

constexpr std::size_t kMaxNameLength = 64;

InputError invalid_name(const std::string& message) { return InputError("invalid_name", message).in_field("name"); }

bool is_name_character(char c, bool first) {
  const bool letter = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_';
  return letter || (!first && c >= '0' && c <= '9');
}

}  // namespace

void check_glsl_name(std::string_view name) {
  if (name.empty() || name.size() > kMaxNameLength) {
    throw invalid_name("a name has 1 to " + std::to_string(kMaxNameLength) + " characters");
  }
  for (std::size_t i = 0; i < name.size(); ++i) {
    if (!is_name_character(name[i], i == 0)) {
      throw invalid_name("a name is [A-Za-z_][A-Za-z0-9_]* (letters, digits, _; not starting with a digit)");
    }
  }
  // What every identifier derived from the name starts with (glsl_name.hpp): the
  // reserved forms are checked on it, not only on the name given.
  const std::string prefix = std::string(name) + "_";
  if (prefix.starts_with("gl_")) {
    throw invalid_name("'" + std::string(name) + "' would make identifiers starting with gl_ (" + prefix +
                       "sdf), which GLSL reserves for its built-ins");
  }
  if (prefix.find("__") != std::string::npos) {
    throw invalid_name("'" + std::string(name) + "' would make identifiers containing __ (" + prefix +
                       "sdf), which GLSL reserves");
  }
  if (std::binary_search(std::begin(kReserved), std::end(kReserved), name)) {
    throw invalid_name("'" + std::string(name) + "' is a GLSL keyword or reserved word");
  }
}

}  // namespace implicitizer
