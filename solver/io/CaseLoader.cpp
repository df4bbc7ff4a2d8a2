// Case-file parsing with toml++: every key checked against the schema, errors name file:line.
#include "solver/io/CaseLoader.h"

#include "solver/core/InputError.h"
#include "solver/core/TextDistance.h"
#include "solver/io/SafeFile.h"
#include "solver/scene/CaseSchema.h"
#include "solver/scene/CaseValidation.h"

#include <toml++/toml.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>

namespace lbdem::io {

using solver::CaseSchema;
using solver::CaseSpec;
using solver::InputError;
using solver::ParamDecl;
using solver::ParamType;
using solver::ParamValue;

namespace {

/// Where each key was set, so that cross-key problems can name a line.
using KeyLines = std::map<std::string, int>;

/// How a message names the kind of a TOML value.
std::string describeNode(const toml::node& node) {
    static constexpr std::pair<toml::node_type, const char*> kKinds[] = {
        {toml::node_type::table, "a table"},           {toml::node_type::array, "an array"},
        {toml::node_type::string, "a string"},         {toml::node_type::integer, "a whole number"},
        {toml::node_type::floating_point, "a number"}, {toml::node_type::boolean, "a boolean"}};
    for (const auto& [type, words] : kKinds)
        if (node.type() == type) return words;
    return "a date or time";
}

std::optional<ParamValue> nodeValue(const toml::node& node) {
    if (auto v = node.value_exact<bool>()) return ParamValue{*v};
    if (auto v = node.value_exact<int64_t>()) return ParamValue{static_cast<long long>(*v)};
    if (auto v = node.value_exact<double>()) return ParamValue{*v};
    if (auto v = node.value_exact<std::string>()) return ParamValue{*v};
    return std::nullopt;
}

std::string suggestion(const std::string& path) {
    const std::string nearest = solver::nearestWord(path, CaseSchema::instance().paths());
    return nearest.empty() ? "" : "; did you mean '" + nearest + "'?";
}

void applyNode(CaseSpec& spec, const std::string& path, const toml::node& node,
               const std::string& source, int line, KeyLines& lines) {
    const ParamDecl* decl = CaseSchema::instance().find(path);
    if (!decl) throw InputError(source, line, path, "unknown key" + suggestion(path));
    const auto value = nodeValue(node);
    if (!value)
        throw InputError(source, line, path,
                         "expected " + std::string(solver::describeType(decl->type)) + ", got " +
                             describeNode(node));
    if (const std::string problem = decl->check(*value); !problem.empty())
        throw InputError(source, line, path, problem);
    decl->set(spec, *value);
    lines[path] = line;
}

void applyTable(CaseSpec& spec, const toml::table& root, const std::string& source,
                KeyLines& lines) {
    const auto sections = CaseSchema::instance().sections();
    for (const auto& [key, node] : root) {
        const std::string name(key.str());
        const int line = static_cast<int>(key.source().begin.line);
        if (const auto* table = node.as_table()) {
            bool known = false;
            for (const auto& section : sections)
                known = known || (section == name && !name.empty());
            if (!known) {
                const std::string nearest = solver::nearestWord(name, sections);
                throw InputError(source, line, name,
                                 "unknown section [" + name + "]" +
                                     (nearest.empty() ? "" : "; did you mean [" + nearest + "]?"));
            }
            for (const auto& [subkey, subnode] : *table)
                applyNode(spec, name + "." + std::string(subkey.str()), subnode, source,
                          static_cast<int>(subkey.source().begin.line), lines);
        } else {
            applyNode(spec, name, node, source, line, lines);
        }
    }
    if (!root.contains("schema"))
        throw InputError(source, 1, "schema", "missing; put 'schema = 1' at the top of the case");
}

ParamValue parseOverrideValue(const ParamDecl& decl, const std::string& text,
                              const std::string& assignment) {
    switch (decl.type) {
    case ParamType::Bool:
        if (text == "true") return true;
        if (text == "false") return false;
        break;
    case ParamType::Integer: {
        errno = 0;
        char* end = nullptr;
        const long long value = std::strtoll(text.c_str(), &end, 10);
        if (!text.empty() && *end == '\0' && errno == 0) return value;
        break;
    }
    case ParamType::Real: {
        errno = 0;
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (!text.empty() && *end == '\0' && errno == 0) return value;
        break;
    }
    case ParamType::Text:
    case ParamType::Choice: {
        std::string word = text;
        if (word.size() >= 2 && word.front() == '"' && word.back() == '"')
            word = word.substr(1, word.size() - 2);
        return word;
    }
    }
    throw InputError("--set " + assignment, 0, decl.path(),
                     "expected " + std::string(solver::describeType(decl.type)) + ", got '" + text +
                         "'");
}

void checkConsistency(const CaseSpec& spec, const std::string& source, const KeyLines& lines) {
    const auto problems = solver::validateCase(spec);
    if (problems.empty()) return;
    const auto& first = problems.front();
    const auto where = lines.find(first.path);
    const int line = where == lines.end() ? 0 : where->second;
    throw InputError(line < 0 ? std::string("--set") : source, line < 0 ? 0 : line, first.path,
                     first.message);
}

CaseSpec parseWithOverrides(const std::string& text, const std::string& source,
                            const std::vector<std::string>& overrides) {
    toml::table root;
    try {
        root = toml::parse(text, source);
    } catch (const toml::parse_error& error) {
        throw InputError(source, static_cast<int>(error.source().begin.line), "",
                         "is not valid TOML: " + std::string(error.description()));
    }
    CaseSpec spec = solver::defaultCase();
    KeyLines lines;
    applyTable(spec, root, source, lines);
    for (const auto& assignment : overrides) {
        applyOverride(spec, assignment);
        lines[assignment.substr(0, assignment.find('='))] = -1;
    }
    checkConsistency(spec, source, lines);
    return spec;
}

} // namespace

void applyOverride(CaseSpec& spec, const std::string& assignment) {
    const auto equals = assignment.find('=');
    if (equals == std::string::npos || equals == 0)
        throw InputError("--set " + assignment + ": expected section.key=value");
    const std::string path = assignment.substr(0, equals);
    const std::string text = assignment.substr(equals + 1);
    const ParamDecl* decl = CaseSchema::instance().find(path);
    if (!decl) throw InputError("--set " + assignment, 0, path, "unknown key" + suggestion(path));
    const ParamValue value = parseOverrideValue(*decl, text, assignment);
    if (const std::string problem = decl->check(value); !problem.empty())
        throw InputError("--set " + assignment, 0, path, problem);
    decl->set(spec, value);
}

CaseSpec parseCase(const std::string& text, const std::string& source,
                   const std::vector<std::string>& overrides) {
    return parseWithOverrides(text, source, overrides);
}

CaseSpec loadCase(const std::string& path, const std::vector<std::string>& overrides) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error))
        throw InputError(path +
                         " is a folder, not a case file (lbdem resume takes a run's folder)");
    return parseWithOverrides(readInputFile(path, "case file"), path, overrides);
}

} // namespace lbdem::io
