#pragma once
/// \file
/// `implicitizer render`: arguments → RenderRequest → answer_render_request() → a PNG file.

#include <span>
#include <string>

namespace implicitizer::cli {

/// Runs the command on the words after `render`; returns the exit status.
int run_render_command(std::span<const std::string> args);

}  // namespace implicitizer::cli
