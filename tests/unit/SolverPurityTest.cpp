// The physics core must not depend on Qt, VTK, HDF5 or TOML (docs/design.md §1 and docs/style.md,
// Style §1).
#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>
#include <QtTest>

class SolverPurityTest : public QObject {
    Q_OBJECT
private slots:
    void noForbiddenIncludesOutsideIo();
    void detectorCatchesForbiddenInclude();
};

namespace {

const QRegularExpression kForbidden(
    R"(^\s*#\s*include\s*[<"](Q[A-Za-z]+|vtk[A-Za-z0-9_]+|hdf5|H5[A-Za-z_]*|toml\+\+/)[^>"]*[>"])",
    QRegularExpression::MultilineOption);

QStringList forbiddenIncludes(const QString& text) {
    QStringList found;
    auto it = kForbidden.globalMatch(text);
    while (it.hasNext())
        found << it.next().captured(0).trimmed();
    return found;
}

} // namespace

void SolverPurityTest::noForbiddenIncludesOutsideIo() {
    const QString root = QStringLiteral(LBDEM_SOURCE_DIR "/solver");
    QDirIterator it(root, {"*.h", "*.hpp", "*.cpp", "*.cc"}, QDir::Files,
                    QDirIterator::Subdirectories);
    int checked = 0;
    QStringList offenders;
    while (it.hasNext()) {
        const QString path = it.next();
        if (path.startsWith(root + "/io/")) continue;
        QFile file(path);
        QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable("cannot read " + path));
        for (const auto& include : forbiddenIncludes(QString::fromUtf8(file.readAll())))
            offenders << path.mid(root.size() - 6) + ": " + include;
        ++checked;
    }
    QVERIFY2(checked > 5, "the solver sources were not found");
    QVERIFY2(offenders.isEmpty(), qPrintable(offenders.join("\n")));
}

void SolverPurityTest::detectorCatchesForbiddenInclude() {
    QCOMPARE(forbiddenIncludes("#include <QObject>\n").size(), 1);
    QCOMPARE(forbiddenIncludes("  #include \"vtkPolyData.h\"\n").size(), 1);
    QCOMPARE(forbiddenIncludes("#include <hdf5.h>\n").size(), 1);
    QCOMPARE(forbiddenIncludes("#include <toml++/toml.h>\n").size(), 1);
    QCOMPARE(forbiddenIncludes("#include <Eigen/Core>\n#include \"solver/core/Real.h\"\n").size(),
             0);
}

QTEST_APPLESS_MAIN(SolverPurityTest)
#include "SolverPurityTest.moc"
