#pragma once
// The `facet` tool's exit codes, shared by every command.

namespace facet::app {

/// Exit codes shared by every command: 0 success, 1 failure while working, 2 bad input.
enum ExitCode : int { kOk = 0, kFailed = 1, kBadInput = 2 };

}  // namespace facet::app
