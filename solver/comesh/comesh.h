// Comesh Optimization (paper section 4.6, Algorithm 1): block-cyclic descent over keys on the
// objective of eq. 8 (comesh_energy.h). Each inner iteration on key i flips edges, splits edges,
// takes one projected gradient step on X_i (interior vertices move freely, boundary vertices slide
// along key i's outline) and collapses edges (comesh_topology.h). Features, interior features
// (ComeshBoundary::pinned), cut ends and cut sides in the keys that close them stay fixed; every
// triangle stays positive in every key.
#pragma once

#include "comesh/comesh_mesh.h"
#include "comesh/comesh_topology.h"
#include "multimesh/multimesh.h"

#include <functional>
#include <string>

namespace ib {

struct ComeshOptions {
  int outerIterations = 500;     // paper: max_outer_itr. Default 500.
  // Paper: max_inner_itr, 100 there. Its Table 2 shows about 3 inner iterations per key per sweep;
  // our sub_res stops later, and converging each key to inner_tol before the next one moves spent
  // most of the time on keys that the next sweep moves again. Capped at 7, Comesh is 1.1 to 5.6
  // times faster on the bundled scenes with every key's share of triangles under 20 degrees within
  // 1.5 points of the cap of 100 (3 and 5 were faster and thinned pentagon-star-thin by 3.5 points;
  // docs/benchmarks.md, "bench examples"). Default 7.
  int innerIterations = 7;
  double outerTolerance = 1e-6;  // paper: outer_tol, on the sum over keys of the largest inner residual. Default 1e-6.
  double innerTolerance = 1e-7;  // paper: inner_tol, on one step's relative energy decrease. Default 1e-7.
  // Also stop once `sweepPatience` sweeps over the keys in a row have each lowered eq. 8 by less
  // than this fraction of it and left no fewer thin triangles (smallest angle under 20 degrees,
  // counted over all keys) than the best sweep before. The paper's outer_tol, on our sub_res, keeps
  // going long after the meshes stop improving: on the bundled scenes this is 1.2 to 3.6 times
  // faster with the same angles and MIPS within noise (docs/benchmarks.md, "bench examples"). 0: never.
  // Default 1e-3.
  double sweepTolerance = 1e-3;
  int sweepPatience = 4;  // sweeps; default 4
  // Weight of each key's ODT term (eq. 4 over the key's area) relative to the MIPS terms, in
  // units of the key's area over its squared mean edge length. As printed, eq. 8 weighs ODT by 1,
  // and MIPS (about twice the area) then outweighs ODT (about a quarter of the squared edge
  // length) by roughly the triangle count: the maps improve but slivers appear. Scaled like this
  // both terms are areas, balanced at any resolution. Default 1.
  double odtBalance = 1;
  bool remesh = true;            // flips, splits and collapses; off: vertex steps only. Default on.
  // Threads for the block energy and the preconditioner's solves on meshes of 4000 vertices or
  // more; 0 = all cores. Default 1: on the 2-core VM two threads saved 8% per inner iteration at
  // 17k vertices while the machine was quiet (2.88 instead of 3.14 ms, 2026-11-22) and cost 45%
  // while its other core was busy (threads wait on each other).
  int threads = 1;
  RemeshOptions bounds;          // when to split and collapse (comesh_topology.h)
  // Called after each outer iteration with the iterations done so far, for progress display. Optional.
  std::function<void(int outer, double energy)> progress;
};

// The columns of the paper's Table 2, plus operation counts.
struct ComeshReport {
  int keys = 0;
  int verticesIn = 0, verticesOut = 0;
  int trianglesIn = 0, trianglesOut = 0;
  int cohesiveIn = 0, cohesiveOut = 0;  // cohesive edge pairs, summed over keys
  int outerIterations = 0;
  int innerIterations = 0;              // summed over keys and outer iterations
  RemeshCounts remesh;                  // flips, splits, collapses and their seconds
  double energyIn = 0, energyOut = 0;   // eq. 8, px^2
  double seconds = 0;                   // total
};

// Optimizes `mesh` and returns the result, a multimesh with possibly different topology. Without
// `boundary` every boundary vertex stays where it is and boundary edges are not split.
Multimesh comeshOptimize(const Multimesh& mesh, const ComeshBoundary* boundary, const ComeshOptions& options,
                         ComeshReport* report);

}  // namespace ib
