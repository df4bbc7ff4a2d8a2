// Compares a run's timeseries.csv with its committed golden copy byte for byte and, where they
// differ, says where and by how much, so that a failing golden run shows the size of the change.
//
// Usage: lbdem_compare_timeseries GOLDEN ACTUAL
// Exit 0 when the bytes are identical; 1 when they differ, with the largest difference printed
// relative to its column's scale (the largest |golden value| of the column, so that a column that
// passes through zero is judged on its own scale); 2 on unreadable or malformed files.
#include "solver/io/TimeSeriesWriter.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using lbdem::io::TimeSeriesTable;

// The whole file as bytes, or false when it cannot be read.
bool readBytes(const char* path, std::string& bytes) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream text;
    text << in.rdbuf();
    bytes = text.str();
    return true;
}

// Largest |value| of each column of the golden table (zero for an all-zero column).
std::vector<double> columnScales(const TimeSeriesTable& golden, std::size_t columns) {
    std::vector<double> scale(columns, 0.0);
    for (const auto& row : golden.rows)
        for (std::size_t c = 0; c < row.size() && c < columns; ++c)
            scale[c] = std::max(scale[c], std::abs(row[c]));
    return scale;
}

// Prints the largest difference between two tables of the same shape; false if the shapes differ.
bool reportLargestDifference(const TimeSeriesTable& golden, const TimeSeriesTable& actual) {
    if (golden.columns != actual.columns) {
        std::cerr << "the columns differ (" << golden.columns.size() << " in the golden file, "
                  << actual.columns.size() << " in the run)\n";
        return false;
    }
    if (golden.rows.size() != actual.rows.size()) {
        std::cerr << "golden has " << golden.rows.size() << " rows, the run " << actual.rows.size()
                  << "\n";
        return false;
    }
    const std::vector<std::string>& names = golden.columns;
    const std::vector<double> scale = columnScales(golden, names.size());
    double worst = -1.0;
    std::size_t worstRow = 0, worstColumn = 0;
    for (std::size_t r = 0; r < golden.rows.size(); ++r) {
        const auto& g = golden.rows[r];
        const auto& a = actual.rows[r];
        if (g.size() != names.size() || a.size() != names.size()) {
            std::cerr << "row " << r + 2 << " has " << a.size() << " fields, expected "
                      << names.size() << "\n";
            return false;
        }
        for (std::size_t c = 0; c < names.size(); ++c) {
            if (std::isnan(a[c]) && std::isnan(g[c])) continue; // both cells empty
            const double difference = std::abs(a[c] - g[c]);
            const double relative =
                scale[c] > 0.0 ? difference / scale[c] : (difference > 0.0 ? INFINITY : 0.0);
            if (!(relative <= worst)) { // also catches NaN
                worst = relative;
                worstRow = r;
                worstColumn = c;
            }
        }
    }
    char report[512];
    std::snprintf(report, sizeof report,
                  "largest difference %.3g of the column's scale: %s, line %zu (t/tau_c %.9g): "
                  "golden %.12g, run %.12g\n",
                  worst, names[worstColumn].c_str(), worstRow + 2,
                  golden.rows[worstRow].size() > 1 ? golden.rows[worstRow][1] : 0.0,
                  golden.rows[worstRow][worstColumn], actual.rows[worstRow][worstColumn]);
    std::cerr << report;
    return true;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: lbdem_compare_timeseries GOLDEN ACTUAL\n";
        return 2;
    }
    std::string goldenBytes, actualBytes;
    if (!readBytes(argv[1], goldenBytes) || !readBytes(argv[2], actualBytes)) {
        std::cerr << "cannot read " << argv[1] << " or " << argv[2] << "\n";
        return 2;
    }
    if (goldenBytes == actualBytes) {
        std::cout << "identical bytes (" << goldenBytes.size() << ")\n";
        return 0;
    }
    try {
        reportLargestDifference(lbdem::io::readTimeSeries(argv[1]),
                                lbdem::io::readTimeSeries(argv[2]));
    } catch (const std::exception& error) {
        std::cerr << "the files differ, and one is not a time series: " << error.what() << "\n";
        return 2;
    }
    return 1;
}
