#pragma once
/// \file
/// Identifiers that users choose and the GLSL contains: the prefix of the function
/// NAME_sdf and of its helpers, node names, uniforms. Validation is by allow-list,
/// so no text a user sends can end an identifier and start other GLSL.

#include <string_view>

namespace implicitizer {

/// Throws InputError `invalid_name` (field "name") unless `name` is usable as the
/// prefix NAME of GLSL identifiers in both GLSL ES 3.00 and GLSL 330.
///
/// This is the one place that decides whether the identifiers derived from a name
/// are legal. Every identifier the generators make from a name is NAME + "_" +
/// a suffix that starts with a letter and contains no `__` (NAME_sdf, NAME_sphere,
/// NAME_leaf0, NODE_radius), so checking NAME and NAME_ covers them all:
///   - NAME is [A-Za-z_][A-Za-z0-9_]*, 1 to 64 characters (ASCII only);
///   - NAME_ does not start with `gl_`, which both dialects reserve for built-ins:
///     `gl` itself is refused (it would make gl_sdf), as is any name starting with
///     `gl_`; `GL` and `Gl` are fine (only lower-case gl_ identifiers are reserved;
///     GL_ is reserved for macro names, which these are not);
///   - NAME_ contains no `__` (identifiers containing `__` are reserved): so no `__`
///     in NAME and no `_` at its end;
///   - NAME is not a keyword or reserved word of either dialect (glsl_name.cpp lists
///     them), so the name can also be used alone (a uniform's full name).
void check_glsl_name(std::string_view name);

}  // namespace implicitizer
