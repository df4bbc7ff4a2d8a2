// Registration of each lbdem subcommand on the CLI11 application.
#pragma once

namespace CLI {
class App;
}

namespace lbdem::cli {

/// `lbdem info`: print the plan of a case, or the documented default case.
void addInfoCommand(CLI::App& app, int& exitCode);
/// `lbdem run` and `lbdem resume`: run a case into an output folder, or continue one.
void addRunCommand(CLI::App& app, int& exitCode);
/// `lbdem verify`: run verification cases against analytic or published values.
void addVerifyCommand(CLI::App& app, int& exitCode);
/// `lbdem bench`: memory bandwidth and kernel throughput against the roofline.
void addBenchCommand(CLI::App& app, int& exitCode);
/// `lbdem render`: PNG images of a run's frames (only in builds with LBDEM_GUI).
void addRenderCommand(CLI::App& app, int& exitCode);
/// `lbdem sweep`: run the cases of a sweep file as separate processes, then tabulate them.
void addSweepCommand(CLI::App& app, int& exitCode);
/// `lbdem study`: run a case over several values of a key, then tabulate error against wall time.
void addStudyCommand(CLI::App& app, int& exitCode);

} // namespace lbdem::cli
