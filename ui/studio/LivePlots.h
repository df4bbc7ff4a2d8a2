// The three live plots of a collapse (runout, E_k/E_p0, Froude number) and their data as CSV.
#pragma once

#include "solver/scene/Snapshot.h"

#include <QString>
#include <QWidget>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace lbdem::studio {

class PlotWidget;

/// Plots the metrics of every snapshot shown against t/tau_c and keeps them as rows for CSV.
class LivePlots : public QWidget {
    Q_OBJECT
public:
    /// Metric names plotted (timeseries.csv columns of the collapse scene).
    static constexpr const char* kRunout = "runout_normalised";
    static constexpr const char* kKineticEnergy = "ke_over_ep0";
    static constexpr const char* kFroude = "froude_densimetric";

    explicit LivePlots(QWidget* parent = nullptr);

    /// Add the metrics of snapshot (ignored when its step is not after the last one).
    void addSnapshot(const solver::Snapshot& snapshot);
    /// Forget every point (a new run starts).
    void clear();
    /// Shade behind each live curve the band (min-max, dashed mean) of the finished runs of
    /// caseName in the sweep folder sweepOut (its NAME_sK folders); returns how many runs the
    /// bands are taken over, 0 (and no band) when there is no finished ensemble there.
    int showEnsemble(const std::filesystem::path& sweepOut, const std::string& caseName);
    /// Remove the ensemble bands.
    void clearEnsemble();
    /// The plot of a metric (kRunout, kKineticEnergy or kFroude); null for any other name.
    const PlotWidget* plot(const std::string& metric) const { return plotOf(metric); }
    /// Rows recorded so far.
    std::size_t rowCount() const { return m_rows.size(); }
    /// Write step, time_s, t_over_tc and every metric seen as CSV; throws std::runtime_error
    /// naming the file when it cannot be written.
    void writeCsv(const QString& path) const;

private:
    PlotWidget* plotOf(const std::string& metric) const;

    struct Row {
        long long step;
        double time_s;
        double t_over_tc;
        std::map<std::string, double> metrics;
    };
    PlotWidget* m_runout;
    PlotWidget* m_energy;
    PlotWidget* m_froude;
    std::vector<Row> m_rows;
};

} // namespace lbdem::studio
