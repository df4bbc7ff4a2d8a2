// Formatting of input errors.
#include "solver/core/InputError.h"

namespace lbdem::solver {

namespace {

std::string composeMessage(const std::string& file, int line, const std::string& key,
                           const std::string& what) {
    std::string message;
    if (!file.empty()) {
        message += file;
        if (line > 0) message += ":" + std::to_string(line);
        message += ": ";
    }
    if (!key.empty()) message += "key '" + key + "': ";
    message += what;
    return message;
}

} // namespace

InputError::InputError(const std::string& file, int line, const std::string& key,
                       const std::string& what)
    : std::runtime_error(composeMessage(file, line, key, what)), m_file(file), m_line(line),
      m_key(key) {}

InputError::InputError(const std::string& message) : std::runtime_error(message) {}

} // namespace lbdem::solver
