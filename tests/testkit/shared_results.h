// Results that several test processes compute alike: ctest runs every test case in its own
// process, so a result that four test cases need (the Comesh-optimized scenes, say) would be
// computed four times. sharedResult computes it once per build of the test program and shares it
// through a file: the first process to ask computes and writes it under a lock, the others wait
// for the lock and read the file. A rebuilt test program (its size or time changed) starts afresh,
// so a result never outlives the code that computed it.
#pragma once

#include <functional>
#include <string>

namespace test {

// The bytes `compute` returns for `name` (a file name: letters, digits, '-', '.'), computed at
// most once per test program build on this machine.
std::string sharedResult(const std::string& name, const std::function<std::string()>& compute);

}  // namespace test
