// CSV time series writer and reader.
#include "solver/io/TimeSeriesWriter.h"

#include "solver/core/InputError.h"
#include "solver/io/SafeFile.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace lbdem::io {

namespace {

const std::vector<std::string> kLeadingColumns{"t_s", "t_over_tc", "step"};

std::vector<std::string> splitLine(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream stream(line);
    std::string cell;
    while (std::getline(stream, cell, ','))
        cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    return cells;
}

std::string formatValue(double value) {
    if (!std::isfinite(value)) return "";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", value);
    return buffer;
}

/// The number in a cell (NaN when empty); throws InputError naming the file, line and column
/// when the cell is not a number (a damaged file).
double cellValue(const std::string& cell, const std::string& path, int line,
                 const std::vector<std::string>& columns, std::size_t column) {
    if (cell.empty()) return std::numeric_limits<double>::quiet_NaN();
    char* end = nullptr;
    const double value = std::strtod(cell.c_str(), &end); // subnormals read back too
    if (end != cell.c_str() && *end == '\0') return value;
    const std::string name = column < columns.size() ? columns[column] : "beyond the header";
    throw solver::InputError(
        path, line, "",
        "the cell '" + cell.substr(0, 40) + "' of column " + name +
            " is not a number: the file is damaged (restore it, or run the case again)");
}

} // namespace

double printedValue(double value) {
    const std::string text = formatValue(value);
    return text.empty() ? std::numeric_limits<double>::quiet_NaN()
                        : std::strtod(text.c_str(), nullptr);
}

TimeSeriesWriter::TimeSeriesWriter(const std::string& path, bool append) : m_path(path) {
    if (append) {
        std::ifstream existing(path);
        std::string header;
        if (existing && std::getline(existing, header) && !header.empty())
            m_columns = splitLine(header);
    }
    m_file.open(path, m_columns.empty() ? std::ios::trunc : std::ios::app);
    if (!m_file) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
}

void TimeSeriesWriter::append(const std::map<std::string, double>& metrics) {
    if (m_columns.empty()) {
        for (const auto& name : kLeadingColumns)
            if (metrics.count(name)) m_columns.push_back(name);
        for (const auto& [name, value] : metrics)
            if (std::find(m_columns.begin(), m_columns.end(), name) == m_columns.end())
                m_columns.push_back(name);
        for (std::size_t c = 0; c < m_columns.size(); ++c)
            m_file << (c ? "," : "") << m_columns[c];
        m_file << "\n";
    }
    for (std::size_t c = 0; c < m_columns.size(); ++c) {
        const auto found = metrics.find(m_columns[c]);
        m_file << (c ? "," : "") << (found == metrics.end() ? "" : formatValue(found->second));
    }
    m_file << "\n";
    m_file.flush();
    if (!m_file)
        throw std::runtime_error("cannot write " + m_path + ": " +
                                 writeFailureCause(m_path, errno));
}

std::vector<double> TimeSeriesTable::column(const std::string& name) const {
    const auto found = std::find(columns.begin(), columns.end(), name);
    if (found == columns.end()) return {};
    const auto index = static_cast<std::size_t>(found - columns.begin());
    std::vector<double> values;
    values.reserve(rows.size());
    for (const auto& row : rows)
        values.push_back(index < row.size() ? row[index] : std::nan(""));
    return values;
}

TimeSeriesTable readTimeSeries(const std::string& path) {
    std::ifstream file(path);
    if (!file) throw std::runtime_error("cannot read " + path);
    TimeSeriesTable table;
    std::string line;
    if (!std::getline(file, line)) return table;
    table.columns = splitLine(line);
    for (int number = 2; std::getline(file, line); ++number) {
        if (line.empty()) continue;
        std::vector<double> row;
        for (const auto& cell : splitLine(line))
            row.push_back(cellValue(cell, path, number, table.columns, row.size()));
        table.rows.push_back(std::move(row));
    }
    return table;
}

} // namespace lbdem::io
