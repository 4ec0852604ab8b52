#pragma once
/// \file
/// Identifiers that users choose and the GLSL contains (the function NAME_sdf, and
/// later uniforms and node names). Validation is by allow-list, so no text a user
/// sends can end an identifier and start other GLSL.

#include <string_view>

namespace implicitizer {

/// Throws InputError `invalid_name` (field "name") unless `name` is usable as the
/// prefix NAME of GLSL identifiers in both GLSL ES 3.00 and GLSL 330:
///   - [A-Za-z_][A-Za-z0-9_]*, 1 to 64 characters (ASCII only);
///   - not starting with `gl_` (reserved for built-ins) and containing no `__`, nor
///     ending with `_` (identifiers containing `__` are reserved, and NAME_ + "_sdf"
///     would contain one);
///   - not a keyword or reserved word of either dialect (glsl_name.cpp lists them),
///     so the name can also be used alone later (uniforms, scene nodes).
void check_glsl_name(std::string_view name);

}  // namespace implicitizer
