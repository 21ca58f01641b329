// A command's output folder, created if missing and removed again, with everything in it, unless
// the command keeps it: a failed command leaves behind no folder it created.
#pragma once

#include <filesystem>
#include <string>

namespace ib::cli {

class OutputFolder {
 public:
  // Creates `path` and its missing parents. Throws InputError naming `option` and the path when
  // it cannot.
  OutputFolder(const std::string& path, const std::string& option);
  ~OutputFolder();  // unless kept: removes the outermost folder the constructor created
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  void keep() { kept_ = true; }  // the command succeeded
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::filesystem::path created_;  // the outermost folder that did not exist before; empty: none
  bool kept_ = false;
};

}  // namespace ib::cli
