// Formatting of input errors.
#include "solver/core/InputError.h"

namespace lbdem::solver {

namespace {

/// Length of the valid UTF-8 sequence starting at text[k] (0 when invalid).
std::size_t utf8Length(const std::string& text, std::size_t k) {
    const auto byte = static_cast<unsigned char>(text[k]);
    const std::size_t length = byte < 0x80           ? 1
                               : (byte >> 5) == 0x6  ? 2
                               : (byte >> 4) == 0xE  ? 3
                               : (byte >> 3) == 0x1E ? 4
                                                     : 0;
    if (length == 0 || k + length > text.size()) return 0;
    for (std::size_t m = 1; m < length; ++m)
        if ((static_cast<unsigned char>(text[k + m]) >> 6) != 0x2) return 0;
    return length;
}

/// text fit for one line of a terminal: control characters and invalid UTF-8 become '?', and
/// anything past maxBytes is replaced by a count (hostile input must not flood the terminal).
std::string printable(const std::string& text, std::size_t maxBytes) {
    std::string out;
    std::size_t k = 0;
    while (k < text.size() && out.size() < maxBytes) {
        const std::size_t length = utf8Length(text, k);
        const auto byte = static_cast<unsigned char>(text[k]);
        if (length == 0 || (length == 1 && (byte < 0x20 || byte == 0x7f))) {
            out += '?';
            ++k;
        } else {
            out.append(text, k, length);
            k += length;
        }
    }
    if (k < text.size()) out += "... (" + std::to_string(text.size() - k) + " more bytes)";
    return out;
}

constexpr std::size_t kMaxPartBytes = 200, kMaxMessageBytes = 1000;

std::string composeMessage(const std::string& file, int line, const std::string& key,
                           const std::string& what) {
    std::string message;
    if (!file.empty()) {
        message += printable(file, kMaxPartBytes);
        if (line > 0) message += ":" + std::to_string(line);
        message += ": ";
    }
    if (!key.empty()) message += "key '" + printable(key, kMaxPartBytes) + "': ";
    message += printable(what, kMaxMessageBytes);
    return message;
}

} // namespace

InputError::InputError(const std::string& file, int line, const std::string& key,
                       const std::string& what)
    : std::runtime_error(composeMessage(file, line, key, what)), m_file(file), m_line(line),
      m_key(key) {}

InputError::InputError(const std::string& message)
    : std::runtime_error(printable(message, kMaxMessageBytes)) {}

} // namespace lbdem::solver
