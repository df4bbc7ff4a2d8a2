// timeseries.csv: one row per output time, columns fixed by the first row.
#pragma once

#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace lbdem::io {

/// Appends rows of named metrics to a CSV file, flushing each row so that a killed run keeps
/// every row written before it died.
class TimeSeriesWriter {
public:
    /// Open path; append to an existing file (resume) when append is true and it has a header.
    explicit TimeSeriesWriter(const std::string& path, bool append = false);

    /// Write one row; the first row fixes the columns (t_s, t_over_tc, step first, then sorted).
    /// Later rows must carry the same names; missing values are written empty.
    void append(const std::map<std::string, double>& metrics);

    /// The column names in file order.
    const std::vector<std::string>& columns() const { return m_columns; }

private:
    std::string m_path;
    std::ofstream m_file;
    std::vector<std::string> m_columns;
};

/// The value as timeseries.csv prints it, read back (NaN for non-finite values).
double printedValue(double value);

/// Read a CSV written by TimeSeriesWriter: column names and rows of numbers (NaN where empty).
struct TimeSeriesTable {
    std::vector<std::string> columns;
    std::vector<std::vector<double>> rows;
    /// The values of one column, or an empty vector when it does not exist.
    std::vector<double> column(const std::string& name) const;
};

/// Load a timeseries.csv; throws std::runtime_error when unreadable, InputError naming the file,
/// line and column when a cell is not a number.
TimeSeriesTable readTimeSeries(const std::string& path);

} // namespace lbdem::io
