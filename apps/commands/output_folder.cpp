#include "commands/output_folder.h"

#include "core/error.h"

namespace ib::cli {

namespace fs = std::filesystem;

OutputFolder::OutputFolder(const std::string& path, const std::string& option) : path_(path) {
  std::error_code error;
  for (fs::path p = path_; !p.empty() && !fs::exists(p, error); p = p.parent_path()) created_ = p;
  fs::create_directories(path_, error);
  if (error || !fs::is_directory(path_)) {
    if (!created_.empty()) fs::remove_all(created_, error);
    throw InputError(option + ": cannot create the folder " + path_.string());
  }
}

OutputFolder::~OutputFolder() {
  std::error_code error;  // nothing to report from a destructor: the command's own error is on its way
  if (!kept_ && !created_.empty()) fs::remove_all(created_, error);
}

}  // namespace ib::cli
