// VTK series and PNG frames of a run (only in builds with lbdem::vis).
#include "app/cli/RunSinks.h"

#include "solver/core/InputError.h"

#ifdef LBDEM_HAS_VIS
#include "ui/vis/OffscreenRenderer.h"
#include "ui/vis/VtkRunWriter.h"
#endif

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace lbdem::cli {

#ifdef LBDEM_HAS_VIS
namespace {

/// Writes every n-th output as VTK XML files with .pvd series.
class VtkSink final : public SnapshotSink {
public:
    VtkSink(const std::string& dir, int every, bool resumed, double keepUntilS)
        : m_writer(dir, resumed, keepUntilS), m_every(every) {}
    void write(const solver::Snapshot& snapshot, long long outputIndex) override {
        if (outputIndex % m_every == 0) m_writer.write(snapshot, static_cast<int>(outputIndex));
    }

private:
    vis::VtkRunWriter m_writer;
    int m_every;
};

/// Renders a PNG frame every n-th output into DIR/frames/frame_NNNNNN.png.
class PngSink final : public SnapshotSink {
public:
    PngSink(const std::string& dir, int every) : m_dir(dir + "/frames"), m_every(every) {
        std::filesystem::create_directories(m_dir);
    }
    void write(const solver::Snapshot& snapshot, long long outputIndex) override {
        if (outputIndex % m_every != 0) return;
        if (!m_renderer) m_renderer = std::make_unique<vis::OffscreenRenderer>(kWidth, kHeight);
        char name[32];
        std::snprintf(name, sizeof name, "/frame_%06lld.png", outputIndex);
        m_renderer->renderPng(snapshot, m_dir + name);
    }

private:
    static constexpr int kWidth = 1200, kHeight = 700;
    std::string m_dir;
    int m_every;
    std::unique_ptr<vis::OffscreenRenderer> m_renderer;
};

} // namespace
#endif

bool sinksAvailable() {
#ifdef LBDEM_HAS_VIS
    return true;
#else
    return false;
#endif
}

std::vector<std::unique_ptr<SnapshotSink>> makeRunSinks(const std::string& dir,
                                                        const SinkOptions& options) {
    std::vector<std::unique_ptr<SnapshotSink>> sinks;
#ifdef LBDEM_HAS_VIS
    if (options.vtk)
        sinks.push_back(std::make_unique<VtkSink>(dir, std::max(1, options.vtk_every),
                                                  options.resumed, options.keep_until_s));
    if (options.render_every_tc > 0) {
        const int every = std::max(
            1, static_cast<int>(std::lround(options.render_every_tc / options.output_interval_tc)));
        sinks.push_back(std::make_unique<PngSink>(dir, every));
    }
#else
    if (options.render_every_tc > 0)
        throw solver::InputError(
            "--render-every needs a build with VTK (configure with LBDEM_GUI=ON)");
    (void)dir;
#endif
    return sinks;
}

} // namespace lbdem::cli
