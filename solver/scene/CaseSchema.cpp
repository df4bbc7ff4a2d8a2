// Mechanics of the case schema: checks, lookup and value formatting.
#include "solver/scene/CaseSchema.h"

#include "solver/scene/CaseKeys.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace lbdem::solver {

std::string_view describeType(ParamType type) {
    // In ParamType's order.
    static constexpr std::string_view kWords[] = {"true or false", "a whole number", "a number",
                                                  "a quoted string", "a quoted word"};
    return kWords[static_cast<int>(type)];
}

namespace {

std::string formatNumber(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.10g", value);
    return buffer;
}

std::string describeValueKind(const ParamValue& value) {
    if (std::holds_alternative<bool>(value)) return "a boolean";
    if (std::holds_alternative<long long>(value)) return "a whole number";
    if (std::holds_alternative<double>(value)) return "a number";
    return "a string";
}

} // namespace

std::string ParamDecl::describeRange() const {
    if (type == ParamType::Choice) {
        std::string words;
        for (const auto& choice : choices)
            words += (words.empty() ? "" : ", ") + choice;
        return "one of " + words;
    }
    if (type != ParamType::Integer && type != ParamType::Real) return {};
    const bool hasMin = std::isfinite(min), hasMax = std::isfinite(max);
    if (hasMin && hasMax) return formatNumber(min) + " to " + formatNumber(max);
    if (hasMin) return "at least " + formatNumber(min);
    if (hasMax) return "at most " + formatNumber(max);
    return {};
}

std::string ParamDecl::check(const ParamValue& value) const {
    switch (type) {
    case ParamType::Bool:
        if (!std::holds_alternative<bool>(value))
            return "expected true or false, got " + describeValueKind(value);
        return {};
    case ParamType::Text:
        if (!std::holds_alternative<std::string>(value))
            return "expected a quoted string, got " + describeValueKind(value);
        return {};
    case ParamType::Choice: {
        if (!std::holds_alternative<std::string>(value)) return "expected " + describeRange();
        const auto& word = std::get<std::string>(value);
        for (const auto& choice : choices)
            if (choice == word) return {};
        return "'" + word + "' is not allowed; expected " + describeRange();
    }
    case ParamType::Integer:
    case ParamType::Real: {
        double number = 0.0;
        if (const auto* i = std::get_if<long long>(&value)) {
            number = static_cast<double>(*i);
        } else if (const auto* d = std::get_if<double>(&value)) {
            if (type == ParamType::Integer)
                return "expected a whole number, got " + formatNumber(*d);
            number = *d;
        } else {
            return std::string("expected ") + std::string(describeType(type)) + ", got " +
                   describeValueKind(value);
        }
        if (!std::isfinite(number)) return "expected a finite number";
        if (number < min || number > max)
            return formatNumber(number) + " is out of range; allowed " + describeRange() +
                   (unit.empty() || unit == "-" ? "" : " " + unit);
        return {};
    }
    }
    return {};
}

const CaseSchema& CaseSchema::instance() {
    static const CaseSchema schema;
    return schema;
}

CaseSchema::CaseSchema() {
    declareCaseKeys(*this);
}

const ParamDecl* CaseSchema::find(std::string_view path) const {
    for (const auto& param : m_params)
        if (param.path() == path) return &param;
    return nullptr;
}

std::vector<std::string> CaseSchema::sections() const {
    std::vector<std::string> names;
    for (const auto& param : m_params) {
        bool seen = false;
        for (const auto& name : names)
            seen = seen || name == param.section;
        if (!seen) names.push_back(param.section);
    }
    return names;
}

std::vector<std::string> CaseSchema::paths() const {
    std::vector<std::string> result;
    result.reserve(m_params.size());
    for (const auto& param : m_params)
        result.push_back(param.path());
    return result;
}

CaseSpec defaultCase() {
    static const CaseSpec defaults = [] {
        CaseSpec spec;
        for (const auto& param : CaseSchema::instance().params())
            param.set(spec, param.default_value);
        return spec;
    }();
    return defaults;
}

std::string formatTomlValue(const ParamValue& value) {
    if (const auto* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
    if (const auto* i = std::get_if<long long>(&value)) return std::to_string(*i);
    if (const auto* d = std::get_if<double>(&value)) {
        std::string text = formatNumber(*d);
        if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
        return text;
    }
    std::string quoted = "\"";
    for (const char c : std::get<std::string>(value)) {
        if (c == '"' || c == '\\') quoted += '\\';
        if (c == '\n') {
            quoted += "\\n";
            continue;
        }
        quoted += c;
    }
    return quoted + "\"";
}

} // namespace lbdem::solver
