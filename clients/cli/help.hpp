#pragma once
/// \file
/// The texts of `implicitizer --help` and `implicitizer help COMMAND`
/// (docs/cli.md is the long form).

namespace implicitizer::cli {

/// The overview: commands, exit statuses, where the syntax is described.
extern const char* const kGeneralHelp;
/// `implicitizer implicitize --help`.
extern const char* const kImplicitizeHelp;
/// `implicitizer groebner --help`.
extern const char* const kGroebnerHelp;
/// `implicitizer resultant --help`.
extern const char* const kResultantHelp;
/// `implicitizer sdf --help`.
extern const char* const kSdfHelp;
/// `implicitizer render --help`.
extern const char* const kRenderHelp;

}  // namespace implicitizer::cli
