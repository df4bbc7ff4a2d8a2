// Mechanics of the case schema: checks, lookup and value formatting.
#include "solver/scene/CaseSchema.h"

#include "solver/scene/CaseKeys.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace lbdem::solver {

std::string_view describeType(ParamType type) {
    switch (type) {
    case ParamType::Bool:
        return "true or false";
    case ParamType::Integer:
        return "a whole number";
    case ParamType::Real:
        return "a number";
    case ParamType::Text:
        return "a quoted string";
    case ParamType::Choice:
        return "a quoted word";
    }
    return "a value";
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

ParamDecl makeDecl(const std::string& section, const std::string& key, ParamType type,
                   const std::string& unit, const std::string& doc,
                   double min = -std::numeric_limits<double>::infinity(),
                   double max = std::numeric_limits<double>::infinity()) {
    ParamDecl decl;
    decl.section = section;
    decl.key = key;
    decl.type = type;
    decl.unit = unit;
    decl.doc = doc;
    decl.min = min;
    decl.max = max;
    return decl;
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

void CaseSchema::addBool(const std::string& section, const std::string& key, const std::string& doc,
                         std::function<bool&(CaseSpec&)> field) {
    ParamDecl decl = makeDecl(section, key, ParamType::Bool, "-", doc);
    decl.get = [field](const CaseSpec& spec) {
        return ParamValue{field(const_cast<CaseSpec&>(spec))};
    };
    decl.set = [field](CaseSpec& spec, const ParamValue& value) {
        field(spec) = std::get<bool>(value);
    };
    m_params.push_back(std::move(decl));
}

void CaseSchema::addInteger(const std::string& section, const std::string& key,
                            const std::string& unit, double min, double max, const std::string& doc,
                            std::function<int&(CaseSpec&)> field) {
    ParamDecl decl = makeDecl(section, key, ParamType::Integer, unit, doc, min, max);
    decl.get = [field](const CaseSpec& spec) {
        return ParamValue{static_cast<long long>(field(const_cast<CaseSpec&>(spec)))};
    };
    decl.set = [field](CaseSpec& spec, const ParamValue& value) {
        field(spec) = static_cast<int>(std::get<long long>(value));
    };
    m_params.push_back(std::move(decl));
}

void CaseSchema::addReal(const std::string& section, const std::string& key,
                         const std::string& unit, double min, double max, const std::string& doc,
                         std::function<double&(CaseSpec&)> field) {
    ParamDecl decl = makeDecl(section, key, ParamType::Real, unit, doc, min, max);
    decl.get = [field](const CaseSpec& spec) {
        return ParamValue{field(const_cast<CaseSpec&>(spec))};
    };
    decl.set = [field](CaseSpec& spec, const ParamValue& value) {
        if (const auto* i = std::get_if<long long>(&value))
            field(spec) = static_cast<double>(*i);
        else
            field(spec) = std::get<double>(value);
    };
    m_params.push_back(std::move(decl));
}

void CaseSchema::addText(const std::string& section, const std::string& key, const std::string& doc,
                         std::function<std::string&(CaseSpec&)> field) {
    ParamDecl decl = makeDecl(section, key, ParamType::Text, "-", doc);
    decl.get = [field](const CaseSpec& spec) {
        return ParamValue{field(const_cast<CaseSpec&>(spec))};
    };
    decl.set = [field](CaseSpec& spec, const ParamValue& value) {
        field(spec) = std::get<std::string>(value);
    };
    m_params.push_back(std::move(decl));
}

void CaseSchema::addChoice(const std::string& section, const std::string& key,
                           std::vector<std::string> choices, const std::string& doc,
                           std::function<std::string&(CaseSpec&)> field) {
    addText(section, key, doc, std::move(field));
    m_params.back().type = ParamType::Choice;
    m_params.back().choices = std::move(choices);
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
