// `lbdem render`: PNG images of a run's frames, read back from RUN_DIR/vtk.
#include "app/cli/Cli.h"
#include "app/cli/Commands.h"
#include "solver/core/InputError.h"
#include "solver/io/SafeFile.h"
#include "ui/vis/ForceChainLayer.h"
#include "ui/vis/LayerSet.h"
#include "ui/vis/OffscreenRenderer.h"
#include "ui/vis/SceneView.h"
#include "ui/vis/VtkRunReader.h"
#include "ui/vis/VtkRunWriter.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <vector>

namespace lbdem::cli {

namespace {

struct RenderOptions {
    std::string runDir;
    std::optional<double> time;
    std::string frame;
    bool all = false;
    std::string png;
    std::string size = "1200x800";
    std::string layers = "fluid,grains,chains,outline";
    std::string field = "speed";
    std::string grainColor = "speed";
    double chainThreshold = 1.0;
    std::string fluidRange, grainRange; ///< "MIN,MAX" fixes the colour range; empty: automatic
    bool quiet = false;
};

/// Parses "WxH" into pixels; throws InputError for anything else.
std::pair<int, int> parseSize(const std::string& text) {
    int width = 0, height = 0;
    char extra = 0;
    if (std::sscanf(text.c_str(), "%dx%d%c", &width, &height, &extra) != 2 || width < 16 ||
        height < 16 || width > 16384 || height > 16384)
        throw solver::InputError("--size '" + text +
                                 "': expected WIDTHxHEIGHT in pixels, e.g. "
                                 "1200x800 (16 to 16384 a side)");
    return {width, height};
}

/// Parses "MIN,MAX" (MIN < MAX) into a fixed colour range; empty text keeps the range automatic.
vis::ColorRange parseRange(const std::string& option, const std::string& text) {
    vis::ColorRange range;
    if (text.empty()) return range;
    double low = 0, high = 0;
    char extra = 0;
    if (std::sscanf(text.c_str(), "%lf,%lf%c", &low, &high, &extra) != 2 || !(low < high))
        throw solver::InputError(option + " '" + text +
                                 "': expected MIN,MAX with MIN < MAX, e.g. 0,0.1");
    range.fixed = true;
    range.min = low;
    range.max = high;
    return range;
}

/// The frames to draw: all, the one nearest --time, --frame N, or the last (the default).
std::vector<int> chosenFrames(const RenderOptions& options, const vis::VtkRunReader& reader) {
    std::vector<int> frames;
    if (options.all) {
        for (int k = 0; k < reader.frameCount(); ++k)
            frames.push_back(k);
    } else if (options.time) {
        frames.push_back(reader.frameNearestTime(*options.time));
    } else if (options.frame.empty() || options.frame == "last") {
        frames.push_back(reader.frameCount() - 1);
    } else {
        std::size_t used = 0;
        int frame = -1;
        try {
            frame = std::stoi(options.frame, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != options.frame.size() || frame < 0)
            throw solver::InputError("--frame '" + options.frame +
                                     "': expected a frame number or 'last'");
        frames.push_back(frame);
    }
    return frames;
}

/// Where frame `frame` goes: the --png file, or FRAME_NNNNNN.png inside the --png folder.
std::string outputPath(const RenderOptions& options, int frame) {
    namespace fs = std::filesystem;
    if (!options.all && !fs::is_directory(options.png)) {
        const fs::path parent = fs::path(options.png).parent_path();
        if (!parent.empty()) fs::create_directories(parent);
        return options.png;
    }
    fs::create_directories(options.png);
    return (fs::path(options.png) / vis::vtkFrameFileName("frame", frame, "png")).string();
}

void render(const RenderOptions& options) {
    const auto [width, height] = parseSize(options.size);
    vis::LayerSet layers = vis::parseLayerSet(options.layers);
    layers.fluidField = vis::parseFluidField(options.field);
    layers.grainColoring = vis::parseGrainColoring(options.grainColor);
    layers.fluidRange() = parseRange("--fluid-range", options.fluidRange);
    layers.grainRange() = parseRange("--grain-range", options.grainRange);
    const vis::VtkRunReader reader(options.runDir);
    io::requireWritableFolder(options.all || std::filesystem::is_directory(options.png)
                                  ? options.png
                                  : std::filesystem::path(options.png).parent_path().string());
    const std::vector<int> frames = chosenFrames(options, reader);
    vis::OffscreenRenderer renderer(width, height, layers);
    renderer.view().forceChains().setThreshold(options.chainThreshold);
    for (const int frame : frames) {
        const solver::Snapshot snapshot = reader.read(frame);
        const std::string path = outputPath(options, frame);
        renderer.renderPng(snapshot, path);
        if (!options.quiet)
            std::cout << "wrote " << path << " (frame " << frame << ", " << vis::timeLabel(snapshot)
                      << ")\n";
    }
}

} // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<RenderOptions>();
    auto* command = app.add_subcommand("render", "Render frames of a run (RUN_DIR/vtk) to PNG; "
                                                 "starts a private Xvfb when DISPLAY is unset");
    command->add_option("run_dir", options->runDir, "Run output folder (holding vtk/particles.pvd)")
        ->required();
    auto* time =
        command->add_option("--time", options->time, "Render the frame nearest to T seconds");
    auto* frame =
        command->add_option("--frame", options->frame, "Render frame N, or 'last' (the default)");
    auto* all =
        command->add_flag("--all", options->all, "Render every frame into the --png folder");
    time->excludes(frame)->excludes(all);
    frame->excludes(all);
    command->add_option("--png", options->png, "Output PNG file, or folder (with --all)")
        ->required();
    command->add_option("--size", options->size, "Image size WIDTHxHEIGHT in pixels")
        ->capture_default_str();
    command
        ->add_option("--layers", options->layers,
                     "Comma-separated layers: fluid,grains,chains,outline,streamlines")
        ->capture_default_str();
    command->add_option("--field", options->field, "Fluid colouring: speed, pressure or vorticity")
        ->capture_default_str();
    command->add_option("--grain-color", options->grainColor, "Grain colouring: speed or force")
        ->capture_default_str();
    command
        ->add_option("--chain-threshold", options->chainThreshold,
                     "Draw force chains above this multiple of the mean normal force")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    command->add_option(
        "--fluid-range", options->fluidRange,
        "Fix the fluid colour range to MIN,MAX in the field's SI unit (default: each frame's)");
    command->add_option(
        "--grain-range", options->grainRange,
        "Fix the grain colour range to MIN,MAX in SI units (default: each frame's)");
    command->add_flag("--quiet", options->quiet, "Print nothing but errors");
    command->callback([options, &exitCode] {
        render(*options);
        exitCode = kExitOk;
    });
}

} // namespace lbdem::cli
