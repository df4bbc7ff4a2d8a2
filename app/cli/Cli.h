// The `lbdem` command line: subcommands, error handling and exit codes.
#pragma once

namespace lbdem::cli {

/// Exit codes of every lbdem command: 0 success; 1 a failure that is not the input's (a file that
/// cannot be written, memory exhausted, a sweep or study with failed runs); 2 bad input (case,
/// options, output folder, checkpoint), one sentence naming file, line and key; 3 a run stopped by
/// a stability guard (lattice or DEM; its summary.json says why and its checkpoints stay valid);
/// 128 + the signal (130 SIGINT, 143 SIGTERM) a run stopped by a signal after its checkpoint.
enum ExitCode : int { kExitOk = 0, kExitFailure = 1, kExitBadInput = 2, kExitUnstable = 3 };

/// Parse argv and run the chosen subcommand; returns the process exit code.
int runCli(int argc, char** argv);

} // namespace lbdem::cli
