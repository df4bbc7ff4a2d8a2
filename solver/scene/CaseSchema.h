// The declaration of every case key, once: type, unit, default, range and documentation.
#pragma once

#include "solver/scene/CaseSpec.h"

#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace lbdem::solver {

/// The value a case key can hold.
using ParamValue = std::variant<bool, long long, double, std::string>;

/// The kind of value a key takes.
enum class ParamType { Bool, Integer, Real, Text, Choice };

/// Name of a parameter type as written in messages ("a number", "true or false", ...).
std::string_view describeType(ParamType type);

/// One declared case key (as deal.II's add_parameter: declared once, documented, ranged).
struct ParamDecl {
    std::string section; ///< TOML table, empty for top-level keys
    std::string key;     ///< key inside the table
    ParamType type = ParamType::Real;
    std::string unit;                                      ///< SI unit, or "-" for dimensionless
    std::string doc;                                       ///< one sentence
    double min = -std::numeric_limits<double>::infinity(); ///< inclusive lower bound (numbers)
    double max = std::numeric_limits<double>::infinity();  ///< inclusive upper bound (numbers)
    std::vector<std::string> choices;                      ///< allowed words (Choice)
    std::function<ParamValue(const CaseSpec&)> get;        ///< read the value from a spec
    std::function<void(CaseSpec&, const ParamValue&)> set; ///< store a checked value

    /// "section.key", or "key" for top-level keys.
    std::string path() const { return section.empty() ? key : section + "." + key; }
    /// The value in a default-constructed CaseSpec.
    ParamValue defaultValue() const { return get(CaseSpec{}); }
    /// Empty when value fits type and range; otherwise the reason, as a sentence fragment.
    std::string check(const ParamValue& value) const;
    /// The allowed range or choices in words, e.g. "0.5 to 2" or "one of bgk, mrt, mrt_les".
    std::string describeRange() const;
};

/// All declared case keys in file order.
class CaseSchema {
public:
    /// The schema of this build (built once, immutable).
    static const CaseSchema& instance();

    const std::vector<ParamDecl>& params() const { return m_params; }
    /// The key at "section.key", or nullptr.
    const ParamDecl* find(std::string_view path) const;
    /// Every section name in declaration order ("" for the top level first).
    std::vector<std::string> sections() const;
    /// Every "section.key" path.
    std::vector<std::string> paths() const;

    // Declaration helpers; each binds a key to a field through an accessor.
    void addBool(const std::string& section, const std::string& key, const std::string& doc,
                 std::function<bool&(CaseSpec&)> field);
    void addInteger(const std::string& section, const std::string& key, const std::string& unit,
                    double min, double max, const std::string& doc,
                    std::function<int&(CaseSpec&)> field);
    void addReal(const std::string& section, const std::string& key, const std::string& unit,
                 double min, double max, const std::string& doc,
                 std::function<double&(CaseSpec&)> field);
    void addText(const std::string& section, const std::string& key, const std::string& doc,
                 std::function<std::string&(CaseSpec&)> field);
    void addChoice(const std::string& section, const std::string& key,
                   std::vector<std::string> choices, const std::string& doc,
                   std::function<std::string&(CaseSpec&)> field);

private:
    CaseSchema();
    std::vector<ParamDecl> m_params;
};

/// Render a value as TOML source text (strings quoted and escaped).
std::string formatTomlValue(const ParamValue& value);

} // namespace lbdem::solver
