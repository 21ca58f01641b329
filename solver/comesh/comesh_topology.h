// Edge flips, splits and collapses of Comesh Optimization (paper section 4.6, Figure 13), applied
// to the topology shared by every key, so to all keys at once or not at all. Every operation keeps
// every triangle positive in every key, never touches a feature, never adds an interior edge
// between two boundary vertices, and keeps cut sides collocated where their cut is closed.
#pragma once

#include "comesh/comesh_mesh.h"
#include "comesh/triangle_shapes.h"

namespace ib {

// Bounds in the spirit of Brochu and Bridson 2009 (El Topo): edge lengths relative to the key's
// mean edge length at the start, angles in degrees.
struct RemeshOptions {
  double splitLength = 1.5;     // split an edge longer than this (relative) in every key. Default 1.5.
  double collapseLength = 0.5;  // collapse an edge shorter than this (relative) in every key. Default 0.5.
  double collapseAngle = 10;    // degrees: or one of its opposite angles is smaller in every key. Default 10.
  // A boundary edge may stray at most this far (relative) from the outline it stands for, unless
  // it already did: sliding and collapsing never cut across the outline's corners. Default 0.05.
  double chordTolerance = 0.05;
  // And never more than this (px), so that Comesh keeps the boundary as close to each key's
  // outline as the shared boundary put it (meshing/shared_boundary.h). Default 0.3.
  double outlineTolerance = 0.3;
};

// Operations applied and seconds spent, summed over calls.
struct RemeshCounts {
  int flips = 0, splits = 0, collapses = 0;
  double flipSeconds = 0, splitSeconds = 0, collapseSeconds = 0;
};

class Remesher {
 public:
  // Takes the relative length unit of every key from `mesh` as it is now.
  Remesher(ComeshMesh& mesh, const RemeshOptions& options);

  // Key k's unit of relative length: its mean edge length at construction (px).
  double unitLength(int k) const { return unit_[k]; }
  // How far boundary edges a -> b -> c, consecutive on the walk, stray from key k's outline
  // (px); c = b for the single edge a -> b.
  double chordDeviation(int k, int a, int b, int c) const;

  // Key k's positions have moved (a vertex step): what the passes cache of every triangle is
  // recomputed in that key before the next pass. Topology changes need no call.
  void keyMoved(int k);

  // One pass over the edges each; return how many operations were applied.
  // Flip: an interior edge whose flip lowers the largest angle of its two triangles over all keys.
  int flipEdges(RemeshCounts& counts);
  // Split at the midpoint (on the outline for boundary edges; a cut edge and its partner together):
  // an edge too long in every key, when no new angle is below collapseAngle and the largest angle
  // does not grow.
  int splitEdges(RemeshCounts& counts);
  // Collapse a vertex onto a neighbour (a boundary vertex that slides in every key only along the
  // boundary): the edge too short in every key, or one angle opposite it too small in every key,
  // when the smallest angle around does not get smaller.
  int collapseEdges(RemeshCounts& counts);

 private:
  // The largest angle of a triangle over all keys: its cosine, or 0 when it is not obtuse (no flip
  // can help then, and its size does not matter), and the edge facing it (i: tri[i] -> tri[i+1]).
  struct WorstAngle {
    double cosine = 1;
    int edge = 0;
  };
  // Over all keys, for triangle t.
  WorstAngle worstAngle(int t) const;
  // Brings the per-triangle caches to the current triangle count and recomputes the keys that
  // moved and the triangles that changed: at the start of a pass and after every operation.
  void refreshCaches();
  // Why a triangle's flip candidate was last refused: key `key` gave the two new triangles the
  // largest-angle cosine `after` (not above the old worst). While that key has not moved and the
  // candidate's four corners are the same, `after` is still what that key gives, so a flip is
  // refused again without looking at any key as long as the old worst stays at least as good.
  // Most candidates (obtuse triangles, hundreds per pass at 16 keys) are refused pass after pass.
  struct Refusal {
    int key = 0;                         // also the key asked first next time
    int a = -1, b = -1, c = -1, d = -1;  // the candidate: edge (a, b), third corners c and d
    double after = 0;
    long moves = -1;                     // moves_[key] when refused
    bool stands(int p, int q, int r, int s, double before, const std::vector<long>& keyMoves) const {
      return moves == keyMoves[key] && a == p && b == q && c == r && d == s && !(after > before + kFlipGain);
    }
  };
  // How much a flip must raise the largest-angle cosine to count as lowering the angle.
  static constexpr double kFlipGain = 1e-12;
  // Flipping (a, b) of triangles (a, b, c), (b, a, d) leaves every key positive and every new angle
  // smaller than the largest before (given as its cosine). Asks refusal.key first; a refusal is
  // recorded in `refusal`.
  bool flipImproves(int a, int b, int c, int d, double before, Refusal& refusal) const;
  // The triangle across edge (a, b) of triangle t (b -> a), or -1; remembered per triangle and
  // checked before use, as the topology changes.
  int twinOf(int t, int a, int b);
  bool trySplit(int a, int b);
  bool tryCollapse(int from, int to);
  bool collapsible(int from, int to) const;
  // Bit i set: edge i of triangle t (tri[i] -> tri[i+1]) is, with `collapse`, too short in every
  // key or faces an angle too small in every key; without, too long in every key.
  int edgeCandidates(int t, bool collapse) const;
  double relativeLength(int k, int a, int b) const;
  // Where a new vertex at the middle of boundary edge (a, b) goes in every key (a before b on the walk).
  std::vector<Eigen::Vector2d> boundaryMidpoint(int a, int b, Eigen::RowVectorXd& u) const;

  ComeshMesh& mesh_;
  RemeshOptions options_;
  double cosCollapse_;        // cosine of options_.collapseAngle
  double cosFlipFloor_;       // cosine of 5 degrees: no flip thins a key under it and under what it had
  std::vector<double> unit_;  // [key]: mean edge length at construction
  // Every triangle's largest angle and candidate edges in every key: the flip test needs every
  // key of every triangle, while a vertex step moves only one key.
  TriangleShapes shapes_;
  std::vector<Refusal> refusals_;        // [triangle]: its flip candidate's last refusal
  std::vector<long> moves_;              // [key]: keyMoved calls
  std::vector<int> twin_;                // [triangle]: the last twin found by twinOf (a hint), or -1
};

}  // namespace ib
