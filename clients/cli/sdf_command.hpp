#pragma once
/// \file
/// `implicitizer sdf`: arguments → SdfRequest → answer_sdf_request().

#include <span>
#include <string>

namespace implicitizer::cli {

/// Runs the command on the words after `sdf`; returns the exit status.
int run_sdf_command(std::span<const std::string> args);

}  // namespace implicitizer::cli
