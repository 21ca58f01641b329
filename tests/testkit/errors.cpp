#include "testkit/errors.h"

#include "core/error.h"

namespace test {

std::string inputError(const std::function<void()>& f) {
  try {
    f();
  } catch (const ib::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace test
