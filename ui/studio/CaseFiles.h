// Where case files come from: the sample cases shipped with lbdem and the recently used ones.
#pragma once

#include <QString>
#include <QStringList>

namespace lbdem::studio {

/// The sample_cases folder: $LBDEM_SAMPLE_CASES, else next to the executable (bin/../..),
/// else the source tree this build came from; empty when none exists.
QString sampleCasesDir();

/// The case files among the samples, relative to sampleCasesDir() and sorted: the top-level
/// .toml files and those in paper/ and verification/ (sweeps/ holds sweep files, not cases).
QStringList samplePresets();

/// The recently opened case files kept in QSettings, newest first.
QStringList recentCaseFiles();
/// Put path at the front of the recent files (at most kMaxRecent kept).
void rememberCaseFile(const QString& path);
/// How many recent files are kept.
constexpr int kMaxRecent = 8;

} // namespace lbdem::studio
