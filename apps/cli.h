// Command-line argument helpers shared by the subcommands. Errors are InputErrors (exit 2).
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

namespace ib::cli {

// The most threads any --threads option takes.
constexpr int kMaxThreads = 1024;

// Parsed options of one subcommand: --name value pairs, --flags and positional arguments.
class Arguments {
 public:
  // valueOptions take a value (--threads 2 or --threads=2); flagOptions take none. Anything
  // else starting with "--" is an error naming the option and the command.
  Arguments(const std::string& command, const std::vector<std::string>& args,
            const std::vector<std::string>& valueOptions, const std::vector<std::string>& flagOptions);

  bool flag(const std::string& name) const { return flags_.count(name) > 0; }
  bool has(const std::string& name) const { return values_.count(name) > 0; }
  std::string value(const std::string& name, const std::string& fallback) const;
  int integer(const std::string& name, int fallback, int min, int max) const;
  const std::vector<std::string>& positional() const { return positional_; }

 private:
  std::string command_;
  std::map<std::string, std::string> values_;
  std::map<std::string, bool> flags_;
  std::vector<std::string> positional_;
};

// A subcommand's words with -o spelled --output.
std::vector<std::string> expandShortOutput(const std::vector<std::string>& args);

// When args hold -h or --help: prints `usage` to stdout and returns true.
bool printHelpIfAsked(const std::vector<std::string>& args, const char* usage);

// A comma-separated list of integers, each optionally with a k suffix (x 1000) and in [min, max],
// for option --`option` (named in the error).
std::vector<int> integerList(const std::string& text, const std::string& option, int min, int max);

// A comma-separated list of non-empty words, for option `option` (named in the error).
std::vector<std::string> wordList(const std::string& text, const std::string& option);

// "A:B" (inclusive, A <= B) or "A", both whole numbers >= 0, for option `option` (named in errors).
std::array<int, 2> frameRange(const std::string& text, const std::string& option);

// InputError for --frames `frames` reaching past a timeline of `frameCount` frames: checked
// before the long work, so a wrong range fails fast.
void checkFramesInTimeline(const std::array<int, 2>& frames, int frameCount);

// A finite number in (0, max], for option `option` (named in errors, with `what` it is, e.g.
// "a frame rate").
double positiveNumber(const std::string& text, const std::string& option, double max, const std::string& what);

}  // namespace ib::cli
