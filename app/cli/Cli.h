// The `lbdem` command line: subcommands, error handling and exit codes.
#pragma once

namespace lbdem::cli {

/// Exit codes of every lbdem command.
enum ExitCode : int { kExitOk = 0, kExitFailure = 1, kExitBadInput = 2 };

/// Parse argv and run the chosen subcommand; returns the process exit code.
int runCli(int argc, char** argv);

} // namespace lbdem::cli
