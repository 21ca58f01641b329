#include "meshing/trace_cache.h"

#include <filesystem>
#include <sstream>

namespace ib {

TraceCache::TraceCache() = default;
TraceCache::~TraceCache() = default;

namespace {

// The file's absolute path, modification time and size: a file edited since gets another.
std::string fileStamp(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  std::ostringstream key;
  key << fs::absolute(path, error).string() << '|' << fs::last_write_time(path, error).time_since_epoch().count() << '|'
      << fs::file_size(path, error);
  return key.str();
}

}  // namespace

const RgbaImage& TraceCache::drawing(const std::string& path) {
  const std::string key = fileStamp(path);
  const auto found = drawings_.find(key);
  if (found != drawings_.end()) return found->second;
  RgbaImage image = readPng(path);
  if (drawings_.size() >= kMostEntries) drawings_.clear();  // drawings swapped many times: start again
  return drawings_.emplace(key, std::move(image)).first->second;
}

const TraceCache::Traced& TraceCache::traced(const std::string& path, const TracingOptions& options, const Polyline& holes) {
  std::ostringstream key;
  key.precision(17);
  key << fileStamp(path) << '|' << options.tolerance << '|' << options.minArea << '|' << options.alphaThreshold << '|'
      << options.colorThreshold << '|' << static_cast<int>(options.holes) << '|';
  if (options.background) key << (*options.background)[0] << ',' << (*options.background)[1] << ',' << (*options.background)[2];
  for (const Eigen::Vector2d& h : holes) key << '|' << h.x() << ',' << h.y();
  const auto found = entries_.find(key.str());
  if (found != entries_.end()) {
    ++hits_;
    return found->second;
  }
  const RgbaImage& image = drawing(path);
  Traced t;
  t.size = {image.width, image.height};
  t.outlines = traceOutlines(shapeMask(image, options, holes, path), options, path);
  if (entries_.size() >= kMostEntries) entries_.clear();  // drawings traced many ways: start again
  return entries_.emplace(key.str(), std::move(t)).first->second;
}

}  // namespace ib
