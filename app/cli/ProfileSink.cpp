// Outline and probe-line CSV files at every output of a run.
#include "app/cli/ProfileSink.h"

#include "solver/io/CaseWriter.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace lbdem::cli {

namespace {

/// A CSV cell with `digits` significant digits (7 for float data, 9 for double); empty when not
/// finite.
std::string cell(double value, int digits = 9) {
    if (!std::isfinite(value)) return "";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
    return buffer;
}

/// Writes the profiles of each output into DIR/profiles/.
class ProfileSink final : public SnapshotSink {
public:
    explicit ProfileSink(const std::string& dir) : m_dir(std::filesystem::path(dir) / "profiles") {
        std::error_code error;
        std::filesystem::create_directories(m_dir, error);
        if (error)
            throw std::runtime_error("cannot create " + m_dir.string() + ": " + error.message());
    }

    void write(const solver::Snapshot& snapshot, long long outputIndex) override {
        if (snapshot.grains.size() > 0)
            io::writeFileAtomically(path("outline", outputIndex), outlineCsv(snapshot));
        for (const auto& [name, probe] : snapshot.probes)
            io::writeFileAtomically(path(name, outputIndex), probeCsv(probe));
    }

private:
    std::string path(const std::string& name, long long outputIndex) const {
        char number[24];
        std::snprintf(number, sizeof number, "_%06lld.csv", outputIndex);
        return (m_dir / (name + number)).string();
    }

    std::filesystem::path m_dir;
};

} // namespace

std::string outlineCsv(const solver::Snapshot& snapshot) {
    std::string text = "x_m,y_m\n";
    for (const auto& [x, y] : snapshot.outline)
        text += cell(x, 7) + "," + cell(y, 7) + "\n";
    return text;
}

std::string probeCsv(const solver::SnapshotProbe& probe) {
    std::string text = "s_m,x_m,y_m," + probe.quantity + "\n";
    for (std::size_t k = 0; k < probe.size(); ++k)
        text += cell(probe.s[k]) + "," + cell(probe.x[k]) + "," + cell(probe.y[k]) + "," +
                cell(probe.value[k]) + "\n";
    return text;
}

std::unique_ptr<SnapshotSink> makeProfileSink(const std::string& dir) {
    return std::make_unique<ProfileSink>(dir);
}

} // namespace lbdem::cli
