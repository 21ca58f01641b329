#include "commands/bench_launcher.h"

#include "core/error.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace ib {

void runBenchProgram(const std::vector<std::string>& args) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  const fs::path program = (error ? fs::path(".") : self.parent_path()) / "inbetween-bench";
  if (!fs::exists(program, error))
    throw InputError("bench: the benchmarks are the program inbetween-bench, which is not beside this inbetween (" +
                     program.string() + "): build it (cmake --build BUILD) or install it with inbetween");
  std::vector<std::string> words = {program.string()};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  execv(program.c_str(), argv.data());
  throw std::runtime_error("bench: cannot run " + program.string() + ": " + std::strerror(errno));
}

}  // namespace ib
