// Foldover-free maps with a fixed boundary: the untangling method of Garanzha, Kaporin,
// Kudryavtseva, Protais, Ray and Sokolov, "Foldover-free maps in 50 lines of code" (2021).
// Minimizes sum_t area_t [(1 - theta) |J|^2 / chi(det J, eps) + theta (det^2 J + 1) / chi(det J, eps)],
// chi(D, eps) = (D + sqrt(eps^2 + D^2)) / 2, by L-BFGS, shrinking eps as the paper prescribes,
// so that a tangled start (folded triangles) ends with every triangle positively oriented.
#pragma once

#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <functional>
#include <vector>

namespace ib {

struct UntangleOptions {
  double theta = 0.125;        // weight of the area term against the shape term, in (0, 1). Default 1/8.
  int outerIterations = 60;     // eps updates at most. Default 60.
  int innerIterations = 300;    // L-BFGS iterations per eps at most. Default 300.
  int memory = 7;               // L-BFGS history length. Default 7.
  double energyTolerance = 1e-3;  // stop once untangled and the energy changes by less than this, relatively. Default 1e-3.
  // Called after every eps update with the outer iterations done and outerIterations, for
  // progress display (a key of 100k vertices takes minutes). Optional.
  std::function<void(int done, int most)> progress;
};

struct UntangleResult {
  bool injective = false;    // every triangle has positive signed area
  double minArea = 0;        // px^2: the smallest signed triangle area
  int worstTriangle = -1;    // the triangle with that area
  int outerIterations = 0;
  int innerIterations = 0;
};

// rest: positions in which every triangle is positive (n x 2), the shape each triangle should
// keep up to scale. positions: the start (n x 2), updated in place; rows with locked[v] != 0
// never move. The map is scaled so that rest and target have the same total area.
UntangleResult untangle(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& rest,
                        Eigen::MatrixX2d& positions, const std::vector<char>& locked,
                        const UntangleOptions& options);

// Moves the vertices `pins` (interior features) from where they are in `positions` to `targets`
// (px), keeping the map foldover-free: in steps, each carrying the free vertices along by the
// harmonic (uniform-weight) extension of the pins' move and then untangling with the pins held at
// the step's place; a step that cannot be untangled is halved (down to 1/128 of the way). So a
// pin may move far from where the map put it (an eye from one side of the body to the other),
// which untangling a Tutte start with the pins in place cannot always undo. positions: a
// foldover-free map (n x 2), updated in place; locked: the vertices that never move (the
// boundary); the pins end exactly at `targets`. Returns the last untangling's result
// (injective false when even the smallest step folds).
UntangleResult untangleToPins(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& rest,
                              Eigen::MatrixX2d& positions, const std::vector<char>& locked, const std::vector<int>& pins,
                              const std::vector<Eigen::Vector2d>& targets, const UntangleOptions& options);

// The uniform-weight (Tutte) harmonic fill: every vertex not `fixed` goes to the average of its
// neighbours, the fixed ones stay (rows of x, n x 2). False, x unchanged, when the system cannot
// be factorized (a free vertex with no path to a fixed one).
bool harmonicFill(const std::vector<Triangle>& triangles, const std::vector<char>& fixed, Eigen::MatrixX2d& x);

// The smallest signed area over triangles and where it is.
std::pair<double, int> smallestTriangleArea(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& positions);

}  // namespace ib
