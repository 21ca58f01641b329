// Checking the errors code throws, for the tests.
#pragma once

#include <functional>
#include <string>

namespace test {

// The message of the InputError `f` throws ("" when it throws none; other exceptions propagate).
std::string inputError(const std::function<void()>& f);

}  // namespace test
