#include "meshing/trace_cache.h"

#include <filesystem>
#include <sstream>

namespace ib {

TraceCache::TraceCache() = default;
TraceCache::~TraceCache() = default;

const TraceCache::Traced& TraceCache::traced(const std::string& path, const TracingOptions& options, const Polyline& holes) {
  namespace fs = std::filesystem;
  std::ostringstream key;
  key.precision(17);
  std::error_code error;
  const auto time = fs::last_write_time(path, error).time_since_epoch().count();
  const auto size = fs::file_size(path, error);
  key << fs::absolute(path).string() << '|' << time << '|' << size << '|' << options.tolerance << '|' << options.minArea << '|'
      << options.alphaThreshold << '|' << options.colorThreshold << '|' << static_cast<int>(options.holes) << '|';
  if (options.background) key << (*options.background)[0] << ',' << (*options.background)[1] << ',' << (*options.background)[2];
  for (const Eigen::Vector2d& h : holes) key << '|' << h.x() << ',' << h.y();
  const auto found = entries_.find(key.str());
  if (found != entries_.end()) {
    ++hits_;
    return found->second;
  }
  Traced t;
  t.drawing = readPng(path);
  t.size = {t.drawing.width, t.drawing.height};
  t.outlines = traceOutlines(shapeMask(t.drawing, options, holes, path), options, path);
  if (entries_.size() >= kMostEntries) entries_.clear();  // drawings swapped many times: start again
  return entries_.emplace(key.str(), std::move(t)).first->second;
}

}  // namespace ib
