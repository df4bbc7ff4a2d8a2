// Registration of each lbdem subcommand on the CLI11 application.
#pragma once

namespace CLI {
class App;
}

namespace lbdem::cli {

/// `lbdem info`: print the plan of a case, or the documented default case.
void addInfoCommand(CLI::App& app, int& exitCode);
/// `lbdem run`: resolve, plan and run a case into an output folder.
void addRunCommand(CLI::App& app, int& exitCode);
/// `lbdem verify`: run verification cases against analytic or published values.
void addVerifyCommand(CLI::App& app, int& exitCode);

} // namespace lbdem::cli
