// The drawn flow-front outline: marching squares finds a circle's contour, and the outline of a
// column or a slumped pile of discs is a smooth curve along their tops, not a staircase.
#include "solver/diagnostics/MassOutline.h"
#include "solver/diagnostics/Contour.h"
#include "solver/io/CaseLoader.h"
#include "solver/scene/Plan.h"
#include "solver/scene/Simulation.h"

#include <QtTest>
#include <algorithm>
#include <cmath>

using namespace lbdem::solver;

namespace {

/// Discs of given radius at given centres (the outline reads positions and radii only).
struct Discs {
    std::vector<Real> x, y, r, zero;
    void add(double cx, double cy, double radius) {
        x.push_back(cx);
        y.push_back(cy);
        r.push_back(radius);
        zero.push_back(0);
    }
    GrainArrays view() const {
        return {x.size(),    x.data(),    y.data(),    r.data(),   zero.data(),
                zero.data(), zero.data(), zero.data(), zero.data()};
    }
    std::vector<bool> all() const { return std::vector<bool>(x.size(), true); }
};

/// The outline's height above x (the highest crossing of the vertical line there).
double heightAt(const Polyline& line, double x) {
    double height = -1;
    for (std::size_t k = 0; k + 1 < line.size(); ++k) {
        const auto [x0, y0] = line[k];
        const auto [x1, y1] = line[k + 1];
        if ((x0 - x) * (x1 - x) > 0 || x0 == x1) continue;
        height = std::max(height, y0 + (y1 - y0) * (x - x0) / (x1 - x0));
    }
    return height;
}

MassOutlineParams unitParams() {
    MassOutlineParams p;
    p.length_m = 1.0; // the unit discs' diameter
    return p;
}

} // namespace

class MassOutlineTest : public QObject {
    Q_OBJECT
private slots:
    void circleContour() {
        // f = 1 - r / 10 on a grid around the origin: the 0.5 contour is the circle r = 5.
        ScalarGrid grid(41, 41, -10, -10, 0.5);
        for (std::size_t j = 0; j < grid.ny; ++j)
            for (std::size_t i = 0; i < grid.nx; ++i)
                grid.at(i, j) = 1 - std::hypot(grid.x0 + i * grid.h, grid.y0 + j * grid.h) / 10;
        const auto loops = marchingSquares(grid, 0.5);
        QCOMPARE(loops.size(), std::size_t(1));
        for (const auto& [x, y] : loops[0])
            QVERIFY(std::abs(std::hypot(x, y) - 5) < 0.02);
        QVERIFY(std::abs(std::abs(signedArea(loops[0])) - M_PI * 25) < 0.5);
        QVERIFY(axisAlignedShare(loops[0]) < 0.1);
    }

    void saddleKeepsLoopsApart() {
        // Two bumps on a diagonal meeting at one saddle cell: the mean decides; here the
        // centre is outside, so the two loops stay apart.
        ScalarGrid grid(4, 4, 0, 0, 1);
        grid.at(1, 1) = grid.at(2, 2) = 1;
        QCOMPARE(marchingSquares(grid, 0.6).size(), std::size_t(2));
        grid.at(1, 2) = grid.at(2, 1) = 0.5; // the centre's mean 0.75 joins them
        QCOMPARE(marchingSquares(grid, 0.6).size(), std::size_t(1));
    }

    void columnOutlineIsSmoothAndHugsTheTops() {
        // A 20 x 10 column of unit discs against the wall on the base, as in a packing test.
        Discs d;
        for (int i = 0; i < 20; ++i)
            for (int j = 0; j < 10; ++j)
                d.add(0.5 + i, 0.5 + j, 0.5);
        const Polyline line = massOutline(d.view(), d.all(), unitParams());
        QVERIFY(line.size() > 20);
        QCOMPARE(line.front().first, 0.0); // from the wall's foot ...
        QCOMPARE(line.front().second, 0.0);
        QCOMPARE(line.back().second, 0.0); // ... to the front's toe
        QVERIFY2(line.back().first > 20 && line.back().first < 20.4,
                 qPrintable(QString::number(line.back().first)));
        for (const auto& [x, y] : line)
            QVERIFY(x >= 0 && y >= 0);
        // Along the top the outline runs just outside the discs' tops (the 0.2 contour of the
        // smoothed solid fraction lies about a third of a diameter out), never through them.
        for (double x = 0.5; x < 19.6; x += 1.0)
            QVERIFY2(heightAt(line, x) > 10 && heightAt(line, x) < 10.4,
                     qPrintable(QString("x %1: %2").arg(x).arg(heightAt(line, x))));
        const double share = axisAlignedShare(line);
        qInfo("column: %zu points, %.1f %% of the segments axis-aligned", line.size(), 100 * share);
        QVERIFY(share < 0.5);
    }

    void slumpedPileOutlineIsNotAStaircase() {
        // A hexagonally packed pile whose rows shorten upwards: a sloping free surface.
        Discs d;
        for (int j = 0; j < 12; ++j)
            for (int i = 0; i < 40 - 3 * j; ++i)
                d.add(0.5 + i + 0.5 * (j % 2), 0.5 + j * std::sqrt(0.75), 0.5);
        const Polyline line = massOutline(d.view(), d.all(), unitParams());
        const double share = axisAlignedShare(line);
        qInfo("pile: %zu points, %.1f %% of the segments axis-aligned", line.size(), 100 * share);
        QVERIFY(share < 0.5);
        // No disc pokes through by more than a tenth of a diameter.
        for (std::size_t k = 0; k < d.x.size(); ++k)
            QVERIFY(heightAt(line, d.x[k]) > d.y[k] + d.r[k] - 0.1);
    }

    void massClearOfTheBaseIsAClosedLoop() {
        Discs d;
        for (int i = 0; i < 5; ++i)
            d.add(5.0 + i, 5.0, 0.5);
        const Polyline line = massOutline(d.view(), d.all(), unitParams());
        QVERIFY(line.size() > 4);
        QCOMPARE(line.front(), line.back());
        QVERIFY(std::abs(signedArea(line)) > 4);
    }

    void noMainMassNoOutline() {
        Discs d;
        d.add(1, 1, 0.5);
        QVERIFY(massOutline(d.view(), {false}, unitParams()).empty());
    }

    void defaultCaseOutlineIsNotAStaircase() {
        // The default case, shrunk to build in a moment, after a few steps of its collapse.
        const CaseSpec spec =
            lbdem::io::loadCase(LBDEM_SOURCE_DIR "/sample_cases/default.toml",
                                {"grains.count=150", "grains.packing=0.79", "fluid.resolution=4",
                                 "fluid.tau=0.506", "domain.width_m=0.08", "domain.height_m=0.04"});
        Simulation simulation(spec, makePlan(spec));
        for (int k = 0; k < 20; ++k)
            simulation.step();
        const auto snapshot = simulation.snapshot();
        Polyline line;
        for (const auto& [x, y] : snapshot->outline)
            line.emplace_back(x, y);
        const double share = axisAlignedShare(line);
        qInfo("default case: %zu points, %.1f %% of the segments axis-aligned", line.size(),
              100 * share);
        QVERIFY(line.size() > 10);
        QVERIFY(share < 0.5);
    }
};

QTEST_APPLESS_MAIN(MassOutlineTest)
#include "MassOutlineTest.moc"
