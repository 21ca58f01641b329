#include "testkit/shared_results.h"

#include "core/atomic_file.h"
#include "multimesh/multimesh_io.h"
#include "pipeline/scene_multimesh.h"

using ib::writeFileAtomically;

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace test {

namespace fs = std::filesystem;

namespace {

// One folder per build of the running program: named after its size and modification time.
fs::path folderOfThisBuild() {
  const fs::path exe = fs::read_symlink("/proc/self/exe");
  const auto stamp = fs::last_write_time(exe).time_since_epoch().count();
  const fs::path folder = fs::temp_directory_path() /
                          ("inbetween-shared-" + exe.filename().string() + "-" + std::to_string(fs::file_size(exe)) + "-" +
                           std::to_string(stamp));
  if (fs::create_directories(folder)) {  // new build: folders of builds unused for a day go
    std::error_code ignored;
    const auto dayAgo = fs::file_time_type::clock::now() - std::chrono::hours(24);
    for (const auto& entry : fs::directory_iterator(fs::temp_directory_path(), ignored))
      if (entry.path().filename().string().rfind("inbetween-shared-", 0) == 0 && entry.path() != folder &&
          fs::last_write_time(entry.path(), ignored) < dayAgo)
        fs::remove_all(entry.path(), ignored);
  }
  return folder;
}

// An exclusive flock on a file, released when it goes out of scope.
class FileLock {
 public:
  explicit FileLock(const fs::path& path) : fd_(::open(path.c_str(), O_CREAT | O_RDWR, 0644)) {
    if (fd_ < 0 || ::flock(fd_, LOCK_EX) != 0) throw std::runtime_error("shared result: cannot lock " + path.string());
  }
  ~FileLock() {
    ::flock(fd_, LOCK_UN);
    ::close(fd_);
  }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
};

}  // namespace

std::string sharedResult(const std::string& name, const std::function<std::string()>& compute) {
  const fs::path folder = folderOfThisBuild();
  const fs::path file = folder / name;
  const FileLock lock(folder / (name + ".lock"));
  if (fs::exists(file)) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
  }
  const std::string bytes = compute();
  writeFileAtomically(file.string(), bytes);
  return bytes;
}

BundledBuild bundledMultimesh(const ib::Scene& scene, const std::string& name) {
  // The notes first, each as its length in bytes, a newline and its text; then the .ibmesh bytes.
  const std::string bytes = sharedResult("bundled-" + name + ".ibmesh", [&] {
    ib::SceneMultimeshOptions options;
    options.useCache = false;
    const ib::SceneMultimesh built = ib::sceneMultimesh(scene, options);
    std::string out = std::to_string(built.notes.size()) + "\n";
    for (const std::string& note : built.notes) out += std::to_string(note.size()) + "\n" + note;
    return out + ib::encodeMultimesh(*built.multimesh);
  });
  BundledBuild build;
  size_t at = 0;
  const auto number = [&] {
    const size_t end = bytes.find('\n', at);
    const size_t n = std::stoul(bytes.substr(at, end - at));
    at = end + 1;
    return n;
  };
  for (size_t count = number(); count > 0; --count) {
    const size_t size = number();
    build.notes.push_back(bytes.substr(at, size));
    at += size;
  }
  build.multimesh = std::make_shared<const ib::Multimesh>(ib::decodeMultimesh(bytes.substr(at), "the shared multimesh of " + name));
  return build;
}

}  // namespace test
