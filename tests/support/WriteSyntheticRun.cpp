// Development tool: writes a synthetic run folder (RUN_DIR/vtk) to try `lbdem render` on.
#include "tests/support/SyntheticSnapshot.h"

#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
    if (argc < 2 || argc > 4) {
        std::cerr << "usage: lbdem_synthetic_run RUN_DIR [FRAMES=4] [dry]\n";
        return 2;
    }
    try {
        const int frames = argc >= 3 ? std::stoi(argv[2]) : 4;
        const bool wet = !(argc == 4 && std::string(argv[3]) == "dry");
        lbdem::support::writeSyntheticRun(argv[1], frames, wet);
        std::cout << "wrote " << frames << " synthetic frames to " << argv[1] << "/vtk\n";
    } catch (const std::exception& error) {
        std::cerr << "lbdem_synthetic_run: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
