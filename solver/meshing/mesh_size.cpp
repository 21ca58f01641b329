#include "meshing/mesh_size.h"

#include "core/error.h"
#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace ib {

namespace {

double loopLength(const Polyline& loop) {
  double length = 0;
  for (size_t i = 0; i < loop.size(); ++i) length += (loop[(i + 1) % loop.size()] - loop[i]).norm();
  return length;
}

// The edge length at which estimateVertices(area, perimeter, e) is `vertices`: the positive root
// of kInteriorDensity area u^2 + perimeter u - vertices = 0 in u = 1 / e.
double edgeLengthFor(double area, double perimeter, double vertices) {
  const double a = kInteriorDensity * area;
  if (a <= 0) return perimeter > 0 ? perimeter / vertices : kMaxDefaultEdge;
  const double u = (-perimeter + std::sqrt(perimeter * perimeter + 4 * a * vertices)) / (2 * a);
  return 1 / u;
}

// Rounds up to two significant digits, for a suggestion the user types into the scene.
double roundUp2(double x) {
  const double scale = std::pow(10.0, std::floor(std::log10(x)) - 1);
  return std::ceil(x / scale - 1e-9) * scale;
}

std::string thousands(double x) {  // 1234567 -> "1,234,567"
  std::string digits = std::to_string(static_cast<long long>(std::llround(x)));
  for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3) digits.insert(static_cast<size_t>(i), ",");
  return digits;
}

std::string decimal(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

}  // namespace

double tracedArea(const std::vector<Outline>& outlines) {
  double area = 0;
  for (const Outline& o : outlines) {
    area += std::abs(loopArea(o.outer));
    for (const Polyline& h : o.holes) area -= std::abs(loopArea(h));
  }
  return std::max(0.0, area);
}

double tracedPerimeter(const std::vector<Outline>& outlines) {
  double length = 0;
  for (const Outline& o : outlines) {
    length += loopLength(o.outer);
    for (const Polyline& h : o.holes) length += loopLength(h);
  }
  return length;
}

double defaultEdgeLength(const std::vector<std::vector<Outline>>& outlines) {
  double area = 0;
  for (const std::vector<Outline>& key : outlines) area += tracedArea(key);
  if (outlines.empty() || area <= 0) return kMaxDefaultEdge;
  return std::clamp(std::sqrt(area / static_cast<double>(outlines.size())) / kEdgeDivisions, kMinDefaultEdge, kMaxDefaultEdge);
}

double estimateVertices(double area, double perimeter, double edgeLength) {
  return kInteriorDensity * area / (edgeLength * edgeLength) + perimeter / edgeLength;
}

std::string estimatedSize(const std::vector<Outline>& reference, double edgeLength) {
  const double estimate = estimateVertices(tracedArea(reference), tracedPerimeter(reference), edgeLength);
  return "about " + thousands(estimate < 1000 ? estimate : roundUp2(estimate)) + " vertices";
}

bool withinMeshLimit(const Scene& scene, const std::vector<Outline>& reference, double edgeLength) {
  return estimateVertices(tracedArea(reference), tracedPerimeter(reference), edgeLength) <= scene.maxVertices;
}

double meshEdgeLength(const Scene& scene, const std::vector<std::vector<Outline>>& outlines) {
  const std::vector<Outline>& reference = outlines.at(static_cast<size_t>(scene.reference));
  const double area = tracedArea(reference), perimeter = tracedPerimeter(reference);
  double edgeLength = scene.edgeLength;
  if (edgeLength <= 0)  // the default: the rule, and never past the limit
    return std::max(defaultEdgeLength(outlines), edgeLengthFor(area, perimeter, scene.maxVertices));
  const double estimate = estimateVertices(area, perimeter, edgeLength);
  if (estimate <= scene.maxVertices) return edgeLength;
  const std::string file = std::filesystem::path(scene.file).filename().string();
  const double fits = roundUp2(edgeLengthFor(area, perimeter, scene.maxVertices));
  throw InputError(file + ": edge_length " + decimal(edgeLength) + " px would give a multimesh of about " +
                   thousands(estimate) + " vertices (key " + inQuotes(scene.keys[scene.reference].name) + ": " +
                   thousands(area) + " px² of shape, " + thousands(perimeter) + " px of outline), more than max_vertices " +
                   thousands(scene.maxVertices) + ": set \"edge_length\" to " + decimal(fits) +
                   " px or more in the scene, or, if this machine has the time and memory for it, raise \"max_vertices\" "
                   "to about " + thousands(roundUp2(estimate)) + " (docs/drawings-to-multimesh.md, \"Edge length\")");
}

}  // namespace ib
