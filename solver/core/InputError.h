// The one error type for bad user input: a sentence that names file, line and key.
#pragma once

#include <stdexcept>
#include <string>

namespace lbdem::solver {

/// Bad input from a case file, an override or the command line; the CLI turns it into exit code 2.
class InputError : public std::runtime_error {
public:
    /// Build the message "FILE:LINE: key 'KEY': WHAT" from its parts (empty parts are left out).
    InputError(const std::string& file, int line, const std::string& key, const std::string& what);
    /// An input error with a message already complete.
    explicit InputError(const std::string& message);

    const std::string& file() const { return m_file; }
    int line() const { return m_line; }
    const std::string& key() const { return m_key; }

private:
    std::string m_file;
    int m_line = 0;
    std::string m_key;
};

/// A solver run that cannot go on (instability, impossible geometry); the message is a diagnosis.
class SimulationError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace lbdem::solver
