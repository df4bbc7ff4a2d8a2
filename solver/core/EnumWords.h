// Enum <-> word conversion from one table per enum: the words a case file, a message or a report
// writes for an enum's values.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lbdem::solver {

/// One value of an enum and its word.
template <class E> struct EnumWord {
    E value;
    const char* word;
};

// Each enum E with words declares, next to itself and in its own namespace, the one table
//     constexpr std::array<EnumWord<E>, N> enumWords(E) { return {{{E::A, "a"}, ...}}; }
// which the functions below find by argument-dependent lookup.

/// The word of value ("?" for a value its table leaves out).
template <class E> const char* enumWord(E value) {
    for (const auto& entry : enumWords(E{}))
        if (entry.value == value) return entry.word;
    return "?";
}

/// The value whose word is word, or nothing.
template <class E> std::optional<E> enumFromWord(std::string_view word) {
    for (const auto& entry : enumWords(E{}))
        if (word == entry.word) return entry.value;
    return std::nullopt;
}

/// Every value of E, in table order.
template <class E> std::vector<E> enumValues() {
    std::vector<E> values;
    for (const auto& entry : enumWords(E{}))
        values.push_back(entry.value);
    return values;
}

/// The words of values, in their order.
template <class E> std::vector<std::string> enumWordList(const std::vector<E>& values) {
    std::vector<std::string> words;
    for (const E value : values)
        words.emplace_back(enumWord(value));
    return words;
}

} // namespace lbdem::solver
