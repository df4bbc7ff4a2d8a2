// Sweep-file parsing with toml++.
#include "solver/io/SweepFile.h"

#include "solver/core/InputError.h"
#include "solver/core/TextDistance.h"
#include "solver/io/SafeFile.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace lbdem::io {

using solver::InputError;

namespace {

const std::vector<std::string> kSweepKeys{"sweep", "name", "cases", "set", "seeds", "variants"};
const std::vector<std::string> kVariantKeys{"name", "set"};

std::vector<std::string> stringArray(const toml::node& node, const std::string& path,
                                     const std::string& key) {
    const auto* array = node.as_array();
    const int line = static_cast<int>(node.source().begin.line);
    if (!array) throw InputError(path, line, key, "expected an array of quoted strings");
    std::vector<std::string> values;
    for (const auto& item : *array) {
        const auto value = item.value<std::string>();
        if (!value) throw InputError(path, line, key, "expected an array of quoted strings");
        values.push_back(*value);
    }
    return values;
}

/// The seeds array: positive integers, none twice.
std::vector<int> seedArray(const toml::node& node, const std::string& path,
                           const std::string& key) {
    const auto* array = node.as_array();
    const int line = static_cast<int>(node.source().begin.line);
    const std::string expected = "expected an array of distinct positive integers, e.g. [1, 2, 3]";
    if (!array || array->empty()) throw InputError(path, line, key, expected);
    std::vector<int> seeds;
    for (const auto& item : *array) {
        const auto value = item.value<int64_t>();
        if (!item.is_integer() || !value || *value < 1 || *value > 2147483647)
            throw InputError(path, line, key, expected);
        if (std::find(seeds.begin(), seeds.end(), *value) != seeds.end())
            throw InputError(path, line, key,
                             "seed " + std::to_string(*value) + " is listed twice");
        seeds.push_back(static_cast<int>(*value));
    }
    return seeds;
}

/// A variant's name: letters, digits, '_' and '-' (it becomes part of a folder name), neither
/// starting with '_' nor holding "__". Then the last "__" of CASE__VARIANT is the one between
/// them, so that two (case, variant) pairs never share a folder (case a with variant b__c and
/// case a__b with variant c would) and the table can tell the case from the variant.
bool isVariantName(const std::string& name) {
    return !name.empty() && name.size() <= 64 && name.front() != '_' &&
           name.find("__") == std::string::npos &&
           std::all_of(name.begin(), name.end(),
                       [](unsigned char c) { return std::isalnum(c) || c == '_' || c == '-'; });
}

/// The `[[variants]]` array of tables: each with a distinct `name` and an optional `set`.
std::vector<SweepVariant> variantArray(const toml::node& node, const std::string& path) {
    const auto* array = node.as_array();
    const int line = static_cast<int>(node.source().begin.line);
    if (!array || array->empty() || !array->is_array_of_tables())
        throw InputError(path, line, "variants",
                         "expected [[variants]] tables, each with a name and a set array");
    std::vector<SweepVariant> variants;
    for (const auto& item : *array) {
        const auto& table = *item.as_table();
        const int at = static_cast<int>(item.source().begin.line);
        SweepVariant variant;
        for (const auto& [key, value] : table) {
            const std::string name(key.str());
            const int keyLine = static_cast<int>(key.source().begin.line);
            if (name == "name") {
                variant.name = value.value<std::string>().value_or("");
                if (!isVariantName(variant.name))
                    throw InputError(path, keyLine, "variants.name",
                                     "expected 1-64 letters, digits, '_' or '-', not starting "
                                     "with '_' and without '__' (which separates the case's "
                                     "name from the variant's in OUT/CASE__VARIANT)");
            } else if (name == "set") {
                variant.overrides = stringArray(value, path, "variants.set");
            } else {
                const std::string nearest = solver::nearestWord(name, kVariantKeys);
                throw InputError(path, keyLine, "variants." + name,
                                 "unknown key" +
                                     (nearest.empty() ? "" : "; did you mean '" + nearest + "'?"));
            }
        }
        if (variant.name.empty())
            throw InputError(path, at, "variants.name", "missing: each variant needs a name");
        for (const auto& other : variants)
            if (other.name == variant.name)
                throw InputError(path, at, "variants.name",
                                 "variant '" + variant.name + "' is listed twice");
        variants.push_back(variant);
    }
    return variants;
}

} // namespace

SweepSpec loadSweep(const std::string& path) {
    toml::table root;
    const std::string text = readInputFile(path, "sweep file");
    try {
        root = toml::parse(text, path);
    } catch (const toml::parse_error& error) {
        const int line = static_cast<int>(error.source().begin.line);
        throw InputError(path, line, "", "is not valid TOML: " + std::string(error.description()));
    }
    SweepSpec sweep;
    sweep.name = std::filesystem::path(path).stem().string();
    const auto folder = std::filesystem::path(path).parent_path();
    for (const auto& [key, node] : root) {
        const std::string name(key.str());
        const int line = static_cast<int>(key.source().begin.line);
        if (name == "sweep") {
            if (node.value<int64_t>() != 1) throw InputError(path, line, name, "expected 1");
        } else if (name == "name") {
            const auto value = node.value<std::string>();
            if (!value) throw InputError(path, line, name, "expected a quoted string");
            sweep.name = *value;
        } else if (name == "cases") {
            for (const auto& file : stringArray(node, path, name)) {
                const auto resolved = (folder / file).lexically_normal();
                if (!std::filesystem::exists(resolved))
                    throw InputError(path, line, name,
                                     "case file " + resolved.string() + " does not exist");
                sweep.cases.push_back(resolved.string());
            }
        } else if (name == "set") {
            sweep.overrides = stringArray(node, path, name);
        } else if (name == "seeds") {
            sweep.seeds = seedArray(node, path, name);
        } else if (name == "variants") {
            sweep.variants = variantArray(node, path);
        } else {
            const std::string nearest = solver::nearestWord(name, kSweepKeys);
            throw InputError(path, line, name,
                             "unknown key" +
                                 (nearest.empty() ? "" : "; did you mean '" + nearest + "'?"));
        }
    }
    if (!root.contains("sweep"))
        throw InputError(path, 1, "sweep", "missing; put 'sweep = 1' at the top");
    if (sweep.cases.empty()) throw InputError(path, 1, "cases", "the sweep lists no case files");
    return sweep;
}

} // namespace lbdem::io
