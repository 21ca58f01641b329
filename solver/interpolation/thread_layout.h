// How the interpolation solver's threads share a multimesh. Its vertices are renumbered into the
// elimination order of the global matrix H (planElimination), so that each thread's part of the
// Cholesky factor is one block of vertices, and its triangles are grouped by the thread that owns
// their lowest vertex. Every loop of an iteration (the local step and gradient, the solves,
// Anderson's passes, the placement) then gives a thread the same vertices: what it reads it
// mostly wrote itself, in its own core's cache, and the solves need no permutation.
#pragma once

#include "core/thread_block.h"
#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <vector>

namespace ib {

struct ThreadLayout {
  Multimesh mesh;                   // the caller's multimesh renumbered: vertex k is its vertex originalOf[k]
  std::vector<int> originalOf;      // n entries
  std::vector<int> partStart;       // threads + 1 entries: the factor's parts (EliminationPlan::partStart)
  RowSplit vertices;                // thread p's vertices; the last thread's include the top separator
  std::vector<Triangle> triangles;  // mesh's triangles (t), grouped by thread
  std::vector<int> triangleOriginalOf;  // t entries: triangles[k] is the caller's triangle triangleOriginalOf[k]
  Eigen::VectorXd kappa;            // their stiffness (t x 1), in that order
  RowSplit triangleSplit;           // thread p's triangles in that list
};

// The layout of `mesh` for `threads` threads (>= 1). Block boundaries are rounded to 16 rows, so
// vector loops over a block start on a 64-byte line (the factor's parts keep their exact bounds).
ThreadLayout threadLayout(const Multimesh& mesh, int threads);

// Rows of x (n x 2) from the caller's numbering into the layout's, and back.
Eigen::MatrixX2d toLayout(const Eigen::MatrixX2d& x, const std::vector<int>& originalOf);
Eigen::MatrixX2d fromLayout(const Eigen::MatrixX2d& x, const std::vector<int>& originalOf);

}  // namespace ib
