// Comesh Optimization (paper section 4.6, Algorithm 1): block-cyclic descent over keys on the
// objective of eq. 8 (comesh_energy.h). This first stage moves interior vertices only: boundary
// vertices, hence features and cut sides (and so cohesive collocation), stay where they are, and
// the topology is unchanged. Sliding boundary vertices and edge flips, splits and collapses come next.
#pragma once

#include "multimesh.h"

#include <vector>

namespace ib {

struct ComeshOptions {
  int outerIterations = 500;     // paper: max_outer_itr. Default 500.
  int innerIterations = 100;     // paper: max_inner_itr. Default 100.
  double outerTolerance = 1e-6;  // paper: outer_tol, on the sum over keys of the largest inner residual. Default 1e-6.
  double innerTolerance = 1e-7;  // paper: inner_tol, on one step's relative energy decrease. Default 1e-7.
};

struct ComeshReport {
  int outerIterations = 0;
  int innerIterations = 0;  // summed over keys and outer iterations
  double seconds = 0;
};

// Optimizes the positions of every key in place. movable[v] != 0 for vertices that may move (the
// interior ones). Every triangle stays positive in every key: a vertex's step is halved until its
// one-ring stays positive (at most 30 times, else it stays).
ComeshReport comeshOptimize(Multimesh& mesh, const std::vector<char>& movable, const ComeshOptions& options);

// movable for comeshOptimize: vertices not on the mesh boundary.
std::vector<char> interiorVertices(const Multimesh& mesh);

}  // namespace ib
