// A 64-bit checksum of byte strings, to tell a damaged file from an intact one.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

namespace lbdem::solver {

/// A 64-bit hash of bytes in 8-byte words: FNV-1a's offset and prime with an extra xor-shift
/// so that every bit of a word reaches every bit of the hash; a tail shorter than a word is
/// zero-padded. Detects damage, not tampering.
class Checksum {
public:
    /// Add bytes, then their length, so that moving bytes between two adds changes the sum.
    void add(const void* data, std::size_t bytes) {
        const auto* p = static_cast<const unsigned char*>(data);
        std::size_t k = 0;
        for (; k + 8 <= bytes; k += 8) {
            std::uint64_t word;
            std::memcpy(&word, p + k, 8);
            mix(word);
        }
        if (k < bytes) {
            std::uint64_t word = 0;
            std::memcpy(&word, p + k, bytes - k);
            mix(word);
        }
        mix(bytes);
    }
    /// Add the bytes of a text.
    void add(const std::string& text) { add(text.data(), text.size()); }
    /// The sum so far as 16 lower-case hex digits.
    std::string hex() const {
        char text[24];
        std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(m_hash));
        return text;
    }

private:
    void mix(std::uint64_t word) {
        m_hash = (m_hash ^ word) * 0x100000001b3ULL;
        m_hash ^= m_hash >> 29;
    }
    std::uint64_t m_hash = 0xcbf29ce484222325ULL;
};

/// The checksum of one text, as hex.
inline std::string checksumOf(const std::string& text) {
    Checksum sum;
    sum.add(text);
    return sum.hex();
}

} // namespace lbdem::solver
