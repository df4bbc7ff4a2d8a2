// Compares a run's timeseries.csv with its committed golden copy byte for byte and, where they
// differ, says where and by how much, so that a failing golden run shows the size of the change.
//
// Usage: lbdem_compare_timeseries GOLDEN ACTUAL
// Exit 0 when the bytes are identical; 1 when they differ, with the largest difference printed
// relative to its column's scale (the largest |golden value| of the column, so that a column that
// passes through zero is judged on its own scale); 2 on unreadable or malformed files.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Table {
    std::string header;
    std::vector<std::vector<double>> rows;
};

// The whole file as bytes, or false when it cannot be read.
bool readBytes(const char* path, std::string& bytes) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream text;
    text << in.rdbuf();
    bytes = text.str();
    return true;
}

// Splits CSV text into its header line and rows of numbers; false names the first bad line.
bool parseTable(const std::string& bytes, Table& table, std::string& error) {
    std::istringstream lines(bytes);
    std::string line;
    if (!std::getline(lines, table.header)) {
        error = "no header line";
        return false;
    }
    for (int number = 2; std::getline(lines, line); ++number) {
        std::vector<double> row;
        std::istringstream fields(line);
        std::string field;
        while (std::getline(fields, field, ',')) {
            char* end = nullptr;
            const double value = std::strtod(field.c_str(), &end);
            if (field.empty() || end != field.c_str() + field.size()) {
                error = "line " + std::to_string(number) + " holds '" + field + "', not a number";
                return false;
            }
            row.push_back(value);
        }
        table.rows.push_back(std::move(row));
    }
    return true;
}

// The column names of a header line, for the report.
std::vector<std::string> columnNames(const std::string& header) {
    std::vector<std::string> names;
    std::istringstream fields(header);
    std::string name;
    while (std::getline(fields, name, ','))
        names.push_back(name);
    return names;
}

// Largest |value| of each column of the golden table (zero for an all-zero column).
std::vector<double> columnScales(const Table& golden, std::size_t columns) {
    std::vector<double> scale(columns, 0.0);
    for (const auto& row : golden.rows)
        for (std::size_t c = 0; c < row.size() && c < columns; ++c)
            scale[c] = std::max(scale[c], std::abs(row[c]));
    return scale;
}

// Prints the largest difference between two tables of the same shape; false if the shapes differ.
bool reportLargestDifference(const Table& golden, const Table& actual) {
    if (golden.header != actual.header) {
        std::cerr << "the columns differ:\n  golden: " << golden.header
                  << "\n  actual: " << actual.header << "\n";
        return false;
    }
    if (golden.rows.size() != actual.rows.size()) {
        std::cerr << "golden has " << golden.rows.size() << " rows, the run " << actual.rows.size()
                  << "\n";
        return false;
    }
    const std::vector<std::string> names = columnNames(golden.header);
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
    Table golden, actual;
    std::string error;
    if (!parseTable(goldenBytes, golden, error) || !parseTable(actualBytes, actual, error)) {
        std::cerr << "the files differ, and one is not a time series: " << error << "\n";
        return 2;
    }
    reportLargestDifference(golden, actual);
    return 1;
}
