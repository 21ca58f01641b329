// Traced drawings kept between builds of the same scene (the editor rebuilds after every edit; its
// drawings rarely change): a drawing is traced again only when its file (modification time, size),
// the tracing options or its key's hole points differ. Keeps the drawings as read, too (a few MB
// each, one per file as it is), for the front end that draws them. Not thread-safe: one build
// uses it at a time.
#pragma once

#include "core/png_image.h"
#include "meshing/tracing.h"
#include "scene/meshing_options.h"

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ib {

class TraceCache {
 public:
  TraceCache();
  ~TraceCache();

  struct Traced {
    std::array<int, 2> size{};      // the drawing's width and height, px
    std::vector<Outline> outlines;  // traceOutlines of its shape mask
  };
  // The drawing at `path` traced with `options` and hole points `holes`, from the cache when the
  // file and the inputs are unchanged. InputError as reading and tracing give.
  const Traced& traced(const std::string& path, const TracingOptions& options, const Polyline& holes);
  int hits() const { return hits_; }  // lookups answered from the cache, for tests
  // The drawing at `path` as read (readPng), from the cache while its file is unchanged; the
  // one traced() reads. InputError as reading gives.
  const RgbaImage& drawing(const std::string& path);

  static constexpr size_t kMostEntries = 64;  // traced drawings or drawings kept at most (then that cache starts over)

 private:
  std::map<std::string, Traced> entries_;  // by the inputs' description
  std::map<std::string, RgbaImage> drawings_;  // by the file's path, time and size
  int hits_ = 0;
};

}  // namespace ib
