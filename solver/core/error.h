// Error types shared by the solver library. Libraries throw; only main() turns an error into a
// message and an exit code (InputError -> 2, anything else -> 1).
#pragma once

#include <stdexcept>
#include <string>

namespace ib {

// Bad input from the user: a file, a field, a parameter. The message names what is wrong.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

// For messages: a name in double quotes, as in `key "arch"`.
inline std::string inQuotes(const std::string& name) { return "\"" + name + "\""; }

}  // namespace ib
