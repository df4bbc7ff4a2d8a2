// Packing generator: reproducible from its seed whatever the thread count, and the cache returns
// the same column.
#include "solver/dem/Packing.h"

#include <QTemporaryDir>
#include <QtTest>

#ifdef _OPENMP
#include <omp.h>
#endif

using namespace lbdem::solver::dem;

class DemPackingTest : public QObject {
    Q_OBJECT
private slots:
    void sameSeedSamePacking();
    void sameColumnWhateverTheThreadCount();
    void cacheRoundTripIsExact();
};

namespace {
PackingRequest small(std::uint64_t seed) {
    PackingRequest r;
    r.count = 120;
    r.target = 0.81;
    r.tolerance = 0.01;
    r.seed = seed;
    return r;
}
} // namespace

void DemPackingTest::sameSeedSamePacking() {
    PackingOptions noCache;
    noCache.use_cache = false;
    const Packing a = generatePacking(small(5), noCache);
    const Packing b = generatePacking(small(5), noCache);
    const Packing c = generatePacking(small(6), noCache);
    QCOMPARE(a.x, b.x);
    QCOMPARE(a.y, b.y);
    QCOMPARE(a.radius, b.radius);
    QVERIFY(a.radius != c.radius);
    for (double r : a.radius)
        QVERIFY(r >= 0.6e-3 && r <= 1.08e-3);
    // Every disc inside the walls (within the contact overlap).
    for (std::size_t k = 0; k < a.x.size(); ++k) {
        QVERIFY(a.x[k] - a.radius[k] > -1e-5 && a.x[k] + a.radius[k] < a.width + 1e-5);
        QVERIFY(a.y[k] - a.radius[k] > -1e-5);
    }
    double height = 0;
    QVERIFY(std::abs(packingFraction(a.y, a.radius, a.width, height) - a.fraction) < 1e-12);
}

void DemPackingTest::sameColumnWhateverTheThreadCount() {
    // Split between threads the DEM's force sums round differently, and a deposition turns that
    // into other grain positions: the generator must not see the run's thread count (when it
    // did, four threads gave this column other positions than one thread).
#ifndef _OPENMP
    QSKIP("built without OpenMP: one thread only");
#else
    PackingOptions noCache;
    noCache.use_cache = false;
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const Packing one = generatePacking(small(7), noCache);
    omp_set_num_threads(4);
    const Packing four = generatePacking(small(7), noCache);
    omp_set_num_threads(threads);
    QCOMPARE(four.x, one.x);
    QCOMPARE(four.y, one.y);
#endif
}

void DemPackingTest::cacheRoundTripIsExact() {
    QTemporaryDir dir;
    PackingOptions cached;
    cached.cache_dir = dir.path().toStdString();
    const Packing fresh = generatePacking(small(9), cached);
    QVERIFY(!fresh.from_cache);
    const Packing again = generatePacking(small(9), cached);
    QVERIFY(again.from_cache || !fresh.converged);
    QCOMPARE(again.x, fresh.x);
    QCOMPARE(again.y, fresh.y);
    QCOMPARE(again.fraction, fresh.fraction);
    PackingRequest other = small(9);
    other.material.friction = 0.3;
    QVERIFY(packingCacheKey(other) != packingCacheKey(small(9)));
}

QTEST_APPLESS_MAIN(DemPackingTest)
#include "DemPackingTest.moc"
