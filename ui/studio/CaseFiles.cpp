// Locating sample cases and keeping the recent-files list in QSettings.
#include "ui/studio/CaseFiles.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace lbdem::studio {

namespace {
constexpr const char* kRecentKey = "files/recent";
}

QString sampleCasesDir() {
    QStringList candidates;
    const QString fromEnv = qEnvironmentVariable("LBDEM_SAMPLE_CASES");
    if (!fromEnv.isEmpty()) candidates << fromEnv;
    const QString bin = QCoreApplication::applicationDirPath();
    candidates << bin + "/../sample_cases" << bin + "/../../sample_cases"
               << bin + "/../share/lbdem/sample_cases" << QStringLiteral(LBDEM_SAMPLE_CASES_DIR);
    for (const QString& candidate : candidates)
        if (QFileInfo(candidate + "/default.toml").isFile()) return QDir(candidate).canonicalPath();
    return {};
}

QStringList samplePresets() {
    const QString root = sampleCasesDir();
    if (root.isEmpty()) return {};
    QStringList presets;
    for (const QString& folder : {QString(), QString("paper"), QString("verification")}) {
        const QDir dir(folder.isEmpty() ? root : root + "/" + folder);
        for (const QString& name : dir.entryList({"*.toml"}, QDir::Files, QDir::Name))
            if (!name.startsWith("sweep")) // sweep files list cases; they are not cases
                presets << (folder.isEmpty() ? name : folder + "/" + name);
    }
    return presets;
}

QStringList recentCaseFiles() {
    return QSettings().value(kRecentKey).toStringList();
}

void rememberCaseFile(const QString& path) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    QStringList files = recentCaseFiles();
    files.removeAll(absolute);
    files.prepend(absolute);
    while (files.size() > kMaxRecent)
        files.removeLast();
    QSettings().setValue(kRecentKey, files);
}

} // namespace lbdem::studio
