#pragma once
/// \file
/// `implicitizer implicitize`: flags → ImplicitizeRequest → answer_implicitize_request().

#include <span>
#include <string>

namespace implicitizer::cli {

/// Runs the command on the words after `implicitize`; returns the exit status.
int run_implicitize_command(std::span<const std::string> args);

}  // namespace implicitizer::cli
