#include "cli.h"

#include "core/error.h"
#include "core/suggest.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace ib::cli {

Arguments::Arguments(const std::string& command, const std::vector<std::string>& args,
                     const std::vector<std::string>& valueOptions, const std::vector<std::string>& flagOptions)
    : command_(command) {
  const auto known = [](const std::vector<std::string>& list, const std::string& name) {
    return std::find(list.begin(), list.end(), name) != list.end();
  };
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.rfind("--", 0) != 0) {
      positional_.push_back(arg);
      continue;
    }
    std::string name = arg.substr(2), value;
    const size_t eq = name.find('=');
    const bool inlineValue = eq != std::string::npos;
    if (inlineValue) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
    }
    if (known(flagOptions, name) && !inlineValue) {
      flags_[name] = true;
    } else if (known(valueOptions, name)) {
      if (!inlineValue) {
        if (i + 1 >= args.size()) throw InputError(command_ + ": option --" + name + " needs a value");
        value = args[++i];
      }
      values_[name] = value;
    } else {
      std::vector<std::string> known;
      for (const std::string& option : valueOptions) known.push_back(option);
      for (const std::string& option : flagOptions) known.push_back(option);
      std::string suggestion = didYouMean(name, known);
      if (!suggestion.empty()) suggestion.replace(suggestion.find('"'), 1, "\"--");
      throw InputError(command_ + ": unknown option --" + name + suggestion + " (see `inbetween " + command_ + " --help`)");
    }
  }
}

std::string Arguments::value(const std::string& name, const std::string& fallback) const {
  const auto it = values_.find(name);
  return it == values_.end() ? fallback : it->second;
}

int Arguments::integer(const std::string& name, int fallback, int min, int max) const {
  const auto it = values_.find(name);
  if (it == values_.end()) return fallback;
  char* end = nullptr;
  const long v = std::strtol(it->second.c_str(), &end, 10);
  if (it->second.empty() || *end != '\0' || v < min || v > max)
    throw InputError(command_ + ": --" + name + " must be a whole number in [" + std::to_string(min) + ", " +
                     std::to_string(max) + "], got '" + it->second + "'");
  return static_cast<int>(v);
}

std::vector<std::string> expandShortOutput(const std::vector<std::string>& args) {
  std::vector<std::string> out;
  for (const std::string& a : args) out.push_back(a == "-o" ? "--output" : a);
  return out;
}

bool printHelpIfAsked(const std::vector<std::string>& args, const char* usage) {
  for (const std::string& a : args)
    if (a == "--help" || a == "-h") {
      std::fputs(usage, stdout);
      return true;
    }
  return false;
}

std::vector<int> integerList(const std::string& text, const std::string& option, int min, int max) {
  std::vector<int> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    int factor = 1;
    if (!item.empty() && (item.back() == 'k' || item.back() == 'K')) {
      factor = 1000;
      item.pop_back();
    }
    char* end = nullptr;
    const long v = std::strtol(item.c_str(), &end, 10) * factor;
    if (item.empty() || *end != '\0' || v < min || v > max)
      throw InputError("--" + option + " entry '" + item + "' must be in [" + std::to_string(min) + ", " +
                       std::to_string(max) + "]");
    out.push_back(static_cast<int>(v));
  }
  if (out.empty()) throw InputError("--" + option + " is empty");
  return out;
}

namespace {

int wholeNumber(const std::string& text, const std::string& option) {
  if (text.empty() || text.size() > 9 ||
      !std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    throw InputError(option + ": '" + text + "' is not a whole number");
  return std::atoi(text.c_str());
}

}  // namespace

std::array<int, 2> frameRange(const std::string& text, const std::string& option) {
  const size_t colon = text.find(':');
  if (colon == std::string::npos) {
    const int f = wholeNumber(text, option);
    return {f, f};
  }
  const std::array<int, 2> range{wholeNumber(text.substr(0, colon), option), wholeNumber(text.substr(colon + 1), option)};
  if (range[0] > range[1]) throw InputError(option + ": '" + text + "' ends before it starts");
  return range;
}

void checkFramesInTimeline(const std::array<int, 2>& frames, int frameCount) {
  if (frames[1] >= frameCount)
    throw InputError("--frames: the timeline has frames 0.." + std::to_string(frameCount - 1) + ", asked for " +
                     std::to_string(frames[0]) + ".." + std::to_string(frames[1]) + ": ask for frames within it");
}

double positiveNumber(const std::string& text, const std::string& option, double max, const std::string& what) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value) || value <= 0 || value > max) {
    std::ostringstream range;
    range << max;
    throw InputError(option + ": '" + text + "' is not " + what + " in (0, " + range.str() + "]");
  }
  return value;
}

std::vector<std::string> wordList(const std::string& text, const std::string& option) {
  std::vector<std::string> words;
  std::stringstream in(text);
  std::string word;
  while (std::getline(in, word, ','))
    if (!word.empty()) words.push_back(word);
  if (words.empty()) throw InputError(option + ": '" + text + "' names nothing: give NAME[,NAME...]");
  return words;
}

}  // namespace ib::cli
