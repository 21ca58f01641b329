#include "meshing/multimesh_builder.h"

#include "meshing/trace_cache.h"

#include "core/error.h"
#include "core/plane_geometry.h"
#include "core/png_image.h"
#include "meshing/artwork_regions.h"
#include "meshing/interior_pins.h"
#include "meshing/mesh_size.h"
#include "meshing/shared_boundary.h"
#include "meshing/stiffness_paint.h"
#include "scene/parameters.h"

#include "core/thread_block.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <tuple>

namespace ib {

namespace {

// How often a key that folds under "artwork" is tried again with the outlines matched by arc
// length near the folds (no shape knots there) and no region pins there, before arc length
// everywhere.
constexpr size_t kShapeKnotRetries = 2;
constexpr double kFoldClearance = 3;  // edge lengths: no shape knots this near a fold on those tries

// A choice's word from the parameter table, quoted: `"paired"`.
std::string choiceName(const std::string& parameterName, int value) {
  return inQuotes(formatParameterValue(parameter(parameterName), value));
}

std::string joined(const std::vector<std::string>& parts) {
  std::string out;
  for (const std::string& part : parts) out += (out.empty() ? "" : "; ") + part;
  return out;
}

bool closedIn(const BoundaryArc& arc, int key) {
  return std::find(arc.closedIn.begin(), arc.closedIn.end(), key) != arc.closedIn.end();
}

// The vertices along arc `a` from its start through its end (the next arc's first vertex).
std::vector<int> chainWithEnd(const ReferenceMesh& mesh, int a) {
  std::vector<int> chain = mesh.arcChains[a];
  chain.push_back(mesh.arcEnd[a]);
  return chain;
}

// Positions of every boundary vertex in key k; cut sides the key closes are exact copies.
void placeBoundary(const SharedBoundary& boundary, const ReferenceMesh& mesh, int k, Eigen::MatrixX2d& x) {
  for (size_t v = 0; v < mesh.tags.size(); ++v)
    if (mesh.tags[v].arc >= 0) x.row(v) = boundary.at(k, mesh.tags[v].arc, mesh.tags[v].u).transpose();
  for (size_t a = 0; a < boundary.arcs.size(); ++a) {
    const BoundaryArc& arc = boundary.arcs[a];
    if (arc.partner <= static_cast<int>(a) || !closedIn(arc, k)) continue;
    const std::vector<int> side = chainWithEnd(mesh, static_cast<int>(a)), other = chainWithEnd(mesh, arc.partner);
    for (size_t i = 0; i < side.size(); ++i) x.row(other[other.size() - 1 - i]) = x.row(side[i]);
  }
}

// Cohesive pairs of key k: the edges of each closed cut's two sides, collocated in key k.
std::vector<CohesivePair> cohesivePairs(const SharedBoundary& boundary, const ReferenceMesh& mesh, int k) {
  std::vector<CohesivePair> pairs;
  for (size_t a = 0; a < boundary.arcs.size(); ++a) {
    const BoundaryArc& arc = boundary.arcs[a];
    if (arc.partner <= static_cast<int>(a) || !closedIn(arc, k)) continue;
    const std::vector<int> side = chainWithEnd(mesh, static_cast<int>(a)), other = chainWithEnd(mesh, arc.partner);
    const size_t n = side.size();
    for (size_t i = 0; i + 1 < n; ++i) pairs.push_back({side[i], side[i + 1], other[n - 1 - i], other[n - 2 - i]});
  }
  return pairs;
}

// B_k: boundary vertices on the key's outline (not along the inside of a cut it closes).
std::vector<int> outlineVertices(const SharedBoundary& boundary, const ReferenceMesh& mesh, int k) {
  std::vector<int> previous(boundary.arcs.size());
  for (const auto& loopArcs : boundary.loopArcs)
    for (size_t i = 0; i < loopArcs.size(); ++i) previous[loopArcs[(i + 1) % loopArcs.size()]] = loopArcs[i];
  std::vector<int> out;
  for (size_t v = 0; v < mesh.tags.size(); ++v) {
    const BoundaryTag& t = mesh.tags[v];
    if (t.arc < 0) continue;
    const bool inside = closedIn(boundary.arcs[t.arc], k) && (t.u > 0 || closedIn(boundary.arcs[previous[t.arc]], k));
    if (!inside) out.push_back(static_cast<int>(v));
  }
  return out;
}

std::string formatLength(double px) {
  std::ostringstream out;
  out.precision(3);
  out << px;
  return out.str();
}

// Arcs, fractions and walk order of the reference mesh's boundary vertices, for Comesh sliding.
ComeshBoundary comeshBoundary(const SharedBoundary& boundary, const ReferenceMesh& mesh, const InteriorPins& pins, int keys) {
  ComeshBoundary out;
  const size_t n = mesh.tags.size();
  out.arc.resize(n);
  out.u.resize(n);
  out.next.assign(n, -1);
  for (size_t v = 0; v < n; ++v) {
    out.arc[v] = mesh.tags[v].arc;
    out.u[v] = mesh.tags[v].u;
  }
  for (size_t a = 0; a < boundary.arcs.size(); ++a) {
    const std::vector<int> chain = chainWithEnd(mesh, static_cast<int>(a));
    for (size_t i = 0; i + 1 < chain.size(); ++i) out.next[chain[i]] = chain[i + 1];
    out.closedIn.emplace_back(keys, 0);
    for (int k = 0; k < keys; ++k) out.closedIn.back()[k] = closedIn(boundary.arcs[a], k);
  }
  auto shared = std::make_shared<const SharedBoundary>(boundary);
  out.point = [shared](int key, int arc, double u) { return shared->at(key, arc, u); };
  out.chordDeviation = [shared](int key, int arc, double u0, double u1, double u2) {
    return shared->chordDeviation(key, arc, u0, u1, u2);
  };
  out.arcLength = [shared](int key, int arc) { return shared->arcLength(key, arc); };
  out.pinned.assign(n, 0);
  for (size_t p = 0; p < pins.features; ++p) out.pinned[pins.vertices[p]] = 1;
  for (int v : deepAnchors(mesh, pins)) out.pinned[v] = 1;
  out.heldIn.assign(keys, std::vector<char>(n, 0));
  for (size_t v = 0; v < n; ++v) {
    const int arc = mesh.tags[v].arc, knot = arc >= 0 ? boundary.knotAt(arc, mesh.tags[v].u) : -1;
    if (knot < 0) continue;
    for (int k = 0; k < keys; ++k) out.heldIn[k][v] = boundary.arcs[arc].knotCornerIn[knot][k];
  }
  return out;
}

// Thrown through a key's mapping when another key's progress report failed: that key stops.
struct StopMapping {};

struct Attempt {
  std::optional<Multimesh> multimesh;
  std::vector<KeyReport> report;
  int failedKey = -1;
  Eigen::Vector2d failedAt = Eigen::Vector2d::Zero();
};

// Maps the reference mesh onto key k (x: n x 2, px; starts as the rest positions): its boundary
// placed, inside from the previous map (`start`, may be null) or a Tutte fill for the other keys,
// untangled. Returns the untangling's result, or an injective one when nothing needed untangling.
UntangleResult mapKey(const Scene& scene, const SharedBoundary& boundary, const ReferenceMesh& mesh, const InteriorPins& pins,
                      const std::vector<char>& onBoundary, const std::vector<char>& locked, const Eigen::MatrixX2d& rest,
                      const PreviousMapStart* start, int k, Eigen::MatrixX2d& x, UntangleOptions untangleOptions) {
  placeBoundary(boundary, mesh, k, x);
  // Interior features: the reference key has them in place; every other key is mapped with them
  // free first, then they are moved to the key's placements (untangleToPins).
  const bool pinsMove = k != scene.reference && !pins.vertices.empty();
  if (k != scene.reference && start && start->covers(k)) {
    // From the previous map, with the interior features where this key places them: as it is
    // when that folds nothing, else untangled from there (the folds' neighbourhood first, then
    // the whole inside); a fold that stays is mapped afresh.
    Eigen::MatrixX2d y = x;
    const Eigen::MatrixX2d from = start->positions(k);
    for (Eigen::Index v = 0; v < y.rows(); ++v)
      if (!onBoundary[static_cast<size_t>(v)]) y.row(v) = from.row(v);
    for (size_t p = 0; pinsMove && p < pins.vertices.size(); ++p) y.row(pins.vertices[p]) = pins.targets[k][p].transpose();
    UntangleResult r;
    std::tie(r.minArea, r.worstTriangle) = smallestTriangleArea(mesh.triangles, y);
    r.injective = r.minArea > 0;
    if (!r.injective) r = untangleCarried(mesh.triangles, rest, y, locked, untangleOptions);
    if (r.injective) {
      x = y;
      return r;
    }
  }
  if (k != scene.reference && !harmonicFill(mesh.triangles, onBoundary, x))
    throw std::runtime_error("Tutte embedding: factorization failed");
  UntangleResult r;
  std::tie(r.minArea, r.worstTriangle) = smallestTriangleArea(mesh.triangles, x);
  r.injective = r.minArea > 0;
  if (k == scene.reference && r.injective) return r;
  r = untangle(mesh.triangles, rest, x, pinsMove ? onBoundary : locked, untangleOptions);
  if (r.injective && pinsMove)
    r = untangleToPins(mesh.triangles, rest, x, onBoundary, pins.vertices, pins.targets[k], untangleOptions);
  return r;
}

// Every key mapped, in parallel over the keys (each on its own: the result does not depend on the
// threads). A key that folds fails the attempt: the first such key in key order is reported.
// Progress reports come one at a time; an exception from one (a cancelled build) stops the keys
// not started and is rethrown once the running ones end.
Attempt mapKeys(const Scene& scene, const SharedBoundary& boundary, const ReferenceMesh& mesh, const InteriorPins& pins,
                double edgeLength, const MultimeshBuildOptions& options) {
  const int n = static_cast<int>(mesh.points.size()), m = static_cast<int>(scene.keys.size());
  Eigen::MatrixX2d rest(n, 2);
  for (int v = 0; v < n; ++v) rest.row(v) = mesh.points[v].transpose();
  std::vector<char> locked(n);
  for (int v = 0; v < n; ++v) locked[v] = mesh.tags[v].arc >= 0;
  const std::vector<char> onBoundary = locked;
  for (int v : pins.vertices) locked[v] = 1;  // pinned where each key places its interior feature
  std::optional<PreviousMapStart> start;
  if (options.previous) start.emplace(*options.previous, rest, 2 * edgeLength);
  Attempt out;
  std::vector<Eigen::MatrixX2d> positions(m, rest);
  std::vector<UntangleResult> results(m);
  std::mutex reporting;
  std::exception_ptr error;
  std::atomic<bool> stop{false};
  int started = 0;  // keys begun (under `reporting`): the progress fraction
  auto report = [&](const std::string& what, double fraction) {
    std::lock_guard<std::mutex> lock(reporting);
    if (error) throw StopMapping{};
    if (!options.progress) return;
    try {
      options.progress(what, fraction);
    } catch (...) {
      error = std::current_exception();
      stop = true;
      throw StopMapping{};
    }
  };
  auto map = [&](int k) {
    if (stop) return;
    try {
      double begun = 0;
      {
        std::lock_guard<std::mutex> lock(reporting);
        begun = static_cast<double>(started++) / m;
      }
      report("mapping key " + scene.keys[k].name, begun);
      UntangleOptions untangleOptions = options.untangle;  // progress within the key: minutes at 100k vertices
      untangleOptions.progress = [&, k, begun](int done, int most) {
        report("mapping key " + scene.keys[k].name + " (untangling, step " + std::to_string(done) + ")",
               begun + static_cast<double>(done) / most / m);
      };
      results[k] = mapKey(scene, boundary, mesh, pins, onBoundary, locked, rest, start ? &*start : nullptr, k, positions[k],
                          untangleOptions);
    } catch (const StopMapping&) {
      stop = true;
    } catch (...) {
      std::lock_guard<std::mutex> lock(reporting);
      if (!error) error = std::current_exception();
      stop = true;
    }
  };
  // The reference key first (its own positions: rarely any untangling), then the others side by
  // side. With one other key, it alone gets the team (the untangler's triangle loop is parallel).
  map(scene.reference);
  std::vector<int> others;
  for (int k = 0; k < m; ++k)
    if (k != scene.reference) others.push_back(k);
  const int count = static_cast<int>(others.size());
#pragma omp parallel for schedule(dynamic) num_threads(teamFor(count))
  for (int i = 0; i < count; ++i) map(others[i]);
  if (error) std::rethrow_exception(error);
  for (int k = 0; k < m; ++k) {
    if (results[k].injective) continue;
    const Triangle& t = mesh.triangles[results[k].worstTriangle];
    const Eigen::MatrixX2d& x = positions[k];
    out.failedKey = k;
    out.failedAt = (x.row(t[0]) + x.row(t[1]) + x.row(t[2])).transpose() / 3;
    return out;
  }
  out.multimesh.emplace(n, mesh.triangles);
  for (int k = 0; k < m; ++k) {
    std::vector<CohesivePair> pairs = cohesivePairs(boundary, mesh, k);
    out.report.push_back({scene.keys[k].name, static_cast<int>(pairs.size()),
                          smallestTriangleArea(mesh.triangles, positions[k]).first});
    out.multimesh->addKey(positions[k], std::move(pairs), outlineVertices(boundary, mesh, k));
  }
  paintStiffness(*out.multimesh, scene.stiffness, scene.kappa);
  return out;
}

}  // namespace

BuiltScene buildMultimesh(const Scene& scene, const MultimeshBuildOptions& options) {
  BuiltScene built;
  const int m = static_cast<int>(scene.keys.size());
  // The drawings as read, kept for the artwork's anchors: read once, for tracing, and used by every attempt.
  const bool artwork = scene.correspondence == OutlineCorrespondence::kArtwork;
  std::vector<RgbaImage> drawings;
  for (int k = 0; k < m; ++k) {
    if (options.progress) options.progress("tracing " + scene.keys[k].name, static_cast<double>(k) / m);
    try {
      if (options.traceCache) {
        const TraceCache::Traced& traced = options.traceCache->traced(scene.keys[k].drawing, scene.tracing, scene.keys[k].holes);
        built.drawingSizes.push_back(traced.size);
        built.outlines.push_back(traced.outlines);
        if (artwork) drawings.push_back(options.traceCache->drawing(scene.keys[k].drawing));
      } else {
        RgbaImage image = readPng(scene.keys[k].drawing);
        built.drawingSizes.push_back({image.width, image.height});
        const ShapeMask mask = shapeMask(image, scene.tracing, scene.keys[k].holes, scene.keys[k].drawing);
        built.outlines.push_back(traceOutlines(mask, scene.tracing, scene.keys[k].drawing));
        if (artwork) drawings.push_back(std::move(image));
      }
    } catch (const InputError& e) {
      throw InputError(std::filesystem::path(scene.file).filename().string() + ": key " + inQuotes(scene.keys[k].name) +
                       ": drawing " + e.what());
    }
    built.shapes.push_back(buildKeyShape(scene, k, built.outlines.back(), options.shape));
  }
  const std::string file = std::filesystem::path(scene.file).filename().string();
  // The scene's edge length or the default that follows the drawings; refused past max_vertices
  // before any meshing (meshing/mesh_size.h).
  double edgeLength = meshEdgeLength(scene, built.outlines);
  for (int k = 0; k < m; ++k) checkInteriorFeatures(scene, k, built.outlines[k], built.shapes[k], edgeLength);
  // What is tried until a setting maps every key without folds (BuiltScene::fallback): the scene's
  // corners, then those that hold the correspondence less ("vertices", "paired", "off"), each from
  // the first edge length down to options.refinements finer ones. At every edge length a key that
  // folds under "artwork" is tried again without shape knots or region pins near the folds
  // (kShapeKnotRetries times), then by arc length; if that folds too, the fold is not the
  // artwork's doing, and the finer edge length tries "artwork" again.
  std::vector<CornerHandling> cornerChain = {scene.corners};
  if (scene.corners == CornerHandling::kVertices) cornerChain.push_back(CornerHandling::kPaired);
  if (scene.corners != CornerHandling::kOff) cornerChain.push_back(CornerHandling::kOff);
  const double firstEdgeLength = edgeLength;
  // Under "artwork", the drawings' regions of flat colour matched across keys, once: pinned at each
  // edge length, and knots where they meet the outline in every key (a stripe's ends).
  const std::optional<ArtworkRegions> regionMatch =
      artwork ? std::optional<ArtworkRegions>(ArtworkRegions(drawings, scene.reference)) : std::nullopt;
  const KeyPoints contacts = regionMatch ? regionMatch->contacts(built.outlines) : KeyPoints{};
  std::vector<std::string> fallbacks;  // what folded, one entry per setting given up
  std::string failure;                 // the last fold: `key "k" near (x, y)`
  std::string failedKey;               // that key's name, quoted
  Eigen::Vector2d failedAt(0, 0);      // and the place, px
  bool finerFits = true;
  for (CornerHandling corners : cornerChain) {
    edgeLength = firstEdgeLength;
    built.failedAttempts.clear();  // the refinements of the corners that build; the fallback note tells the rest
    OutlineCorrespondence correspondence = scene.correspondence;
    std::string artworkFolds;            // where "artwork" folded at this edge length, for the note
    std::vector<Eigen::Vector2d> folds;  // those places: no shape knots or region pins near them
    for (int attempt = 0;; ++attempt) {
      SharedBoundaryOptions bo;
      bo.edgeLength = edgeLength;
      bo.corners = corners;
      bo.correspondence = correspondence;
      bo.shapeKnotsClearOf = folds;
      bo.shapeKnotClearance = kFoldClearance * edgeLength;
      bo.artworkKnots = contacts;
      const SharedBoundary boundary = matchBoundaries(scene, built.shapes, bo);
      if (options.progress)
        options.progress("meshing " + scene.keys[scene.reference].name + " (" +
                         estimatedSize(built.outlines[scene.reference], edgeLength) + ")", 0);
      ConformingMeshOptions mo;
      mo.maxEdgeLength = edgeLength;
      const KeyPoints regions =
          correspondence == OutlineCorrespondence::kArtwork
              ? regionPins(scene, *regionMatch, built.shapes, edgeLength, folds, kFoldClearance * edgeLength)
              : KeyPoints{};
      ReferenceMesh mesh;
      try {
        mesh = meshReference(boundary, scene.reference, mo, interiorPoints(scene, scene.reference, edgeLength, regions));
      } catch (const InputError& e) {
        throw InputError(file + ": key " + inQuotes(scene.keys[scene.reference].name) + ": cannot mesh: " + e.what());
      }
      InteriorPins pins = interiorPins(scene, mesh, edgeLength, regions);
      if (correspondence == OutlineCorrespondence::kArtwork) anchorArtwork(drawings, mesh, edgeLength, pins);
      Attempt result = mapKeys(scene, boundary, mesh, pins, edgeLength, options);
      if (result.multimesh) {
        if (!artworkFolds.empty())
          fallbacks.push_back("correspondence \"artwork\" folded " + artworkFolds + " at edge length " + formatLength(edgeLength) +
                              " px" + (correspondence == OutlineCorrespondence::kArtwork
                                           ? "; built with no shape knot or region pin within " +
                                                 formatLength(kFoldClearance * edgeLength) + " px of each fold"
                                           : ""));
        built.multimesh = std::move(result.multimesh);
        built.boundary = comeshBoundary(boundary, mesh, pins, m);
        built.report = std::move(result.report);
        built.edgeLength = edgeLength;
        built.attempts = attempt + 1;
        built.fallback = joined(fallbacks);
        if (corners != scene.corners || correspondence != scene.correspondence)
          built.fallback += "; built with corners " + choiceName("corners", int(corners)) + " and correspondence " +
                            choiceName("correspondence", int(correspondence)) + " instead";
        built.multimesh->validate();
        return built;
      }
      failedKey = inQuotes(scene.keys[result.failedKey].name);
      failedAt = result.failedAt;
      failure = "key " + failedKey + " near " + formatPoint(failedAt);
      if (correspondence == OutlineCorrespondence::kArtwork) {  // tried again at this edge length
        artworkFolds += (artworkFolds.empty() ? "" : ", then ") + failure;
        if (folds.size() < kShapeKnotRetries) folds.push_back(result.failedAt);  // arc length, no region pins near it
        else correspondence = OutlineCorrespondence::kOutline;                  // by arc length everywhere
        --attempt;
        continue;
      }
      built.failedAttempts.push_back("at " + formatLength(edgeLength) + " px, corners " + choiceName("corners", int(corners)) +
                                     ", correspondence " + choiceName("correspondence", int(correspondence)) + ", key " +
                                     failedKey + " folded near " + formatPoint(failedAt) +
                                     (artworkFolds.empty() ? "" : " (under \"artwork\" " + artworkFolds + ")"));
      // Arc length folds here too: not the artwork's doing, so a finer mesh tries it again.
      artworkFolds.clear();
      folds.clear();
      correspondence = scene.correspondence;
      finerFits = withinMeshLimit(scene, built.outlines[scene.reference], edgeLength / 1.5);
      if (attempt >= options.refinements || !finerFits) break;
      edgeLength /= 1.5;
    }
    fallbacks.push_back("corners " + choiceName("corners", int(corners)) + " folded " + failure +
                        " at edge lengths down to " + formatLength(edgeLength) + " px");
  }
  std::string tried;
  for (CornerHandling corners : cornerChain) tried += (tried.empty() ? "" : ", ") + choiceName("corners", int(corners));
  throw InputError(file + ": key " + failedKey + ": cannot map the mesh onto this key without folding triangles near " +
                   formatPoint(failedAt) + " (tried corners " + tried +
                   (scene.correspondence == OutlineCorrespondence::kArtwork ? ", correspondence \"artwork\" and \"outline\"" : "") +
                   ", edge lengths down to " + formatLength(edgeLength) + " px" +
                   (finerFits ? "" : ": a finer one would pass max_vertices") +
                   "); check that its features, interior features and cuts match the other keys there");
}

}  // namespace ib
