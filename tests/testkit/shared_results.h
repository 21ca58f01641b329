// Results that several test processes compute alike: ctest runs every test case in its own
// process, so a result that four test cases need (the Comesh-optimized scenes, say) would be
// computed four times. sharedResult computes it once per build of the test program and shares it
// through a file: the first process to ask computes and writes it under a lock, the others wait
// for the lock and read the file. A rebuilt test program (its size or time changed) starts afresh,
// so a result never outlives the code that computed it.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ib {
class Multimesh;
struct Scene;
}  // namespace ib

namespace test {

// The bytes `compute` returns for `name` (a file name: letters, digits, '-', '.'), computed at
// most once per test program build on this machine.
std::string sharedResult(const std::string& name, const std::function<std::string()>& compute);

// A bundled scene's multimesh as `inbetween mesh` builds it (Comesh, never from a cache) and the
// build's notes, built once per test program build and shared: the test cases that walk every
// bundled scene read it. `name`: the scene's folder name, unique among the bundled scenes.
struct BundledBuild {
  std::shared_ptr<const ib::Multimesh> multimesh;  // never null
  std::vector<std::string> notes;                  // SceneMultimesh::notes
};
BundledBuild bundledMultimesh(const ib::Scene& scene, const std::string& name);

}  // namespace test
