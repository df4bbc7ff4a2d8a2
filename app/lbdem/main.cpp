// `lbdem`: the command-line entry point.
#include "app/cli/Cli.h"

int main(int argc, char** argv) {
    return lbdem::cli::runCli(argc, argv);
}
