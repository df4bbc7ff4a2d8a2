// Feeding the live plots from snapshots and writing their rows as CSV.
#include "ui/studio/LivePlots.h"

#include "campaign/EnsembleBand.h"
#include "solver/io/CaseWriter.h"
#include "ui/studio/PlotWidget.h"

#include <QHBoxLayout>

#include <algorithm>
#include <set>
#include <sstream>
#include <stdexcept>

namespace lbdem::studio {

LivePlots::LivePlots(QWidget* parent) : QWidget(parent) {
    const QString time = QString::fromUtf8("t / \u03c4c");
    m_runout = new PlotWidget(tr("Runout"), time, QString::fromUtf8("\u0394L / L_i"));
    m_energy = new PlotWidget(tr("Kinetic energy"), time, tr("E_k / E_p0"));
    m_froude = new PlotWidget(tr("Densimetric Froude number"), time, tr("Fr_d"));
    // Harbitz et al. (2003): fronts hydroplane above a densimetric Froude number of about 0.4.
    m_froude->setReferenceLine(0.4, tr("hydroplaning 0.4"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    for (PlotWidget* plot : {m_runout, m_energy, m_froude})
        layout->addWidget(plot);
}

void LivePlots::addSnapshot(const solver::Snapshot& snapshot) {
    if (!m_rows.empty() && snapshot.step <= m_rows.back().step) return;
    m_rows.push_back({snapshot.step, snapshot.time_s, snapshot.timeOverTc(), snapshot.metrics});
    const double t = snapshot.timeOverTc();
    auto feed = [&](PlotWidget* plot, const char* name) {
        const auto found = snapshot.metrics.find(name);
        if (found != snapshot.metrics.end())
            plot->addPoint(t, found->second);
        else if (plot->points().isEmpty())
            plot->setEmptyNote(tr("this scene reports no %1").arg(name));
    };
    feed(m_runout, kRunout);
    feed(m_energy, kKineticEnergy);
    feed(m_froude, kFroude);
}

void LivePlots::clear() {
    m_rows.clear();
    for (PlotWidget* plot : {m_runout, m_energy, m_froude}) {
        plot->clear();
        plot->setEmptyNote({});
    }
}

int LivePlots::showEnsemble(const std::filesystem::path& sweepOut, const std::string& caseName) {
    int runs = 0;
    for (const char* metric : {kRunout, kKineticEnergy, kFroude}) {
        const auto band = campaign::loadEnsembleBand(sweepOut, caseName, metric);
        PlotWidget* target = plotOf(metric);
        if (band.runs == 0) {
            target->clearBand();
            continue;
        }
        auto vector = [](const std::vector<double>& values) {
            return QVector<double>(values.begin(), values.end());
        };
        target->setBand(vector(band.t_over_tc), vector(band.min), vector(band.mean),
                        vector(band.max),
                        tr("band: min-max of %1 seeds, dashed: mean").arg(band.runs));
        runs = std::max(runs, band.runs);
    }
    return runs;
}

void LivePlots::clearEnsemble() {
    for (PlotWidget* plot : {m_runout, m_energy, m_froude})
        plot->clearBand();
}

PlotWidget* LivePlots::plotOf(const std::string& metric) const {
    if (metric == kRunout) return m_runout;
    if (metric == kKineticEnergy) return m_energy;
    if (metric == kFroude) return m_froude;
    return nullptr;
}

void LivePlots::writeCsv(const QString& path) const {
    std::set<std::string> names;
    for (const Row& row : m_rows)
        for (const auto& [name, value] : row.metrics)
            names.insert(name);
    names.erase("step"), names.erase("time_s"), names.erase("t_over_tc");
    std::ostringstream csv;
    csv.precision(10);
    csv << "step,time_s,t_over_tc";
    for (const auto& name : names)
        csv << ',' << name;
    csv << '\n';
    for (const Row& row : m_rows) {
        csv << row.step << ',' << row.time_s << ',' << row.t_over_tc;
        for (const auto& name : names) {
            const auto found = row.metrics.find(name);
            csv << ',';
            if (found != row.metrics.end()) csv << found->second;
        }
        csv << '\n';
    }
    io::writeFileAtomically(path.toStdString(), csv.str());
}

} // namespace lbdem::studio
