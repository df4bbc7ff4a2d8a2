// The declaration of every case key, once: type, unit, default, range and documentation.
#pragma once

#include "solver/core/EnumWords.h"
#include "solver/scene/CaseSpec.h"

#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace lbdem::solver {

/// The value a case key can hold.
using ParamValue = std::variant<bool, long long, double, std::string>;

/// The kind of value a key takes (describeType words them in this order).
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
    ParamValue default_value;                              ///< the value of a default case
    std::function<ParamValue(const CaseSpec&)> get;        ///< read the value from a spec
    std::function<void(CaseSpec&, const ParamValue&)> set; ///< store a checked value

    /// "section.key", or "key" for top-level keys.
    std::string path() const { return section.empty() ? key : section + "." + key; }
    /// The value the key takes when a case does not set it.
    const ParamValue& defaultValue() const { return default_value; }
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
    /// Append a declaration (SectionKeys builds them).
    void add(ParamDecl decl) { m_params.push_back(std::move(decl)); }

private:
    CaseSchema();
    std::vector<ParamDecl> m_params;
};

/// The ParamValue a field's value is read and written as: bool, long long (int fields), double,
/// a string (text), or the enum's word from its table (choices).
inline ParamValue toParamValue(bool value) {
    return value;
}
inline ParamValue toParamValue(int value) {
    return static_cast<long long>(value);
}
inline ParamValue toParamValue(double value) {
    return value;
}
inline ParamValue toParamValue(const std::string& value) {
    return value;
}
template <class E, class = std::enable_if_t<std::is_enum_v<E>>> ParamValue toParamValue(E value) {
    return std::string(enumWord(value));
}

/// Store a checked value into a field of the matching type.
inline void fromParamValue(const ParamValue& value, bool& field) {
    field = std::get<bool>(value);
}
inline void fromParamValue(const ParamValue& value, int& field) {
    field = static_cast<int>(std::get<long long>(value));
}
inline void fromParamValue(const ParamValue& value, double& field) {
    const auto* whole = std::get_if<long long>(&value);
    field = whole ? static_cast<double>(*whole) : std::get<double>(value);
}
inline void fromParamValue(const ParamValue& value, std::string& field) {
    field = std::get<std::string>(value);
}
template <class E, class = std::enable_if_t<std::is_enum_v<E>>>
void fromParamValue(const ParamValue& value, E& field) {
    field = enumFromWord<E>(std::get<std::string>(value)).value();
}

/// Declares the keys of one section, each bound to a field of the section's struct in CaseSpec,
/// with its default, unit, range and meaning: "key = default [unit] (range): doc".
template <class Section> class SectionKeys {
public:
    /// The keys of [section], the CaseSpec member part.
    SectionKeys(CaseSchema& schema, std::string section, Section CaseSpec::*part)
        : m_schema(schema), m_section(std::move(section)),
          m_part([part](CaseSpec& spec) -> Section& { return spec.*part; }) {}
    /// The top-level keys, fields of CaseSpec itself (Section = CaseSpec).
    explicit SectionKeys(CaseSchema& schema)
        : m_schema(schema), m_part([](CaseSpec& spec) -> Section& { return spec; }) {}

    /// A true/false key.
    void flag(const char* key, bool Section::*field, bool fallback, const char* doc) {
        bind(declare(key, ParamType::Bool, "-", doc), field, fallback);
    }
    /// A whole-number key in [min, max].
    void integer(const char* key, int Section::*field, int fallback, const char* unit, double min,
                 double max, const char* doc) {
        bind(declare(key, ParamType::Integer, unit, doc, min, max), field, fallback);
    }
    /// A real-number key in [min, max].
    void real(const char* key, double Section::*field, double fallback, const char* unit,
              double min, double max, const char* doc) {
        bind(declare(key, ParamType::Real, unit, doc, min, max), field, fallback);
    }
    /// A free-text key.
    void text(const char* key, std::string Section::*field, const char* fallback, const char* doc) {
        bind(declare(key, ParamType::Text, "-", doc), field, std::string(fallback));
    }
    /// A key holding one of the allowed values of enum E, written as their words (enumWords).
    template <class E>
    void choice(const char* key, E Section::*field, E fallback, const char* doc,
                const std::vector<E>& allowed = enumValues<E>()) {
        ParamDecl decl = declare(key, ParamType::Choice, "-", doc);
        decl.choices = enumWordList(allowed);
        bind(std::move(decl), field, fallback);
    }

private:
    ParamDecl declare(const char* key, ParamType type, const char* unit, const char* doc,
                      double min = -std::numeric_limits<double>::infinity(),
                      double max = std::numeric_limits<double>::infinity()) const {
        ParamDecl decl;
        decl.section = m_section;
        decl.key = key;
        decl.type = type;
        decl.unit = unit;
        decl.doc = doc;
        decl.min = min;
        decl.max = max;
        return decl;
    }

    template <class T> void bind(ParamDecl decl, T Section::*field, const T& fallback) {
        const auto part = m_part;
        decl.default_value = toParamValue(fallback);
        decl.get = [part, field](const CaseSpec& spec) {
            return toParamValue(part(const_cast<CaseSpec&>(spec)).*field);
        };
        decl.set = [part, field](CaseSpec& spec, const ParamValue& value) {
            fromParamValue(value, part(spec).*field);
        };
        m_schema.add(std::move(decl));
    }

    CaseSchema& m_schema;
    std::string m_section;
    std::function<Section&(CaseSpec&)> m_part;
};

/// Render a value as TOML source text (strings quoted and escaped).
std::string formatTomlValue(const ParamValue& value);

} // namespace lbdem::solver
