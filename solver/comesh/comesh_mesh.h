// The multimesh as Comesh Optimization edits it (paper section 4.6, Figure 13): one triangle list
// shared by every key, per-key positions, and for boundary vertices where they sit on the key's
// outline, so that edge flips, splits and collapses can change the shared topology in place and
// boundary vertices can slide. Converted from and back to a Multimesh.
#pragma once

#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <functional>
#include <vector>

namespace ib {

// Where boundary vertices live: every loop of the outline is cut into arcs (docs/design.md, "Loops and arcs"); a boundary
// vertex sits at a fraction u of one arc's length, independently in every key. Vertices at u = 0
// (features, cut ends, the start of a featureless loop) never move.
struct ComeshBoundary {
  std::vector<int> arc;      // [vertex]: its arc, or -1 for an interior vertex
  std::vector<double> u;     // [vertex]: fraction along its arc, the same in every key at the start
  std::vector<int> next;     // [vertex]: the next boundary vertex walking along the arc, or -1
  std::vector<std::vector<char>> closedIn;  // [arc][key]: the arc is one side of a cut closed in that key
  // Key `key`'s point at fraction u in [0, 1] of arc `arc` (px).
  std::function<Eigen::Vector2d(int key, int arc, double u)> point;
  // How far key `key`'s outline between fractions u0 <= u1 <= u2 of arc `arc` strays from the
  // straight chords u0 -> u1 and u1 -> u2 between their points (px; u1 = u2 for one chord): a
  // boundary edge must not cut across the outline's corners. Two chords, because a sliding vertex
  // has two boundary edges.
  std::function<double(int key, int arc, double u0, double u1, double u2)> chordDeviation;
  // Length of arc `arc` in key `key` (px): a vertex moving by du along it moves at most |du| times
  // this. Optional; without it a vertex step tries every halving.
  std::function<double(int key, int arc)> arcLength;
  // [vertex]: an interior vertex that never moves in any key (an interior feature), or empty for
  // none. Like a feature on the outline it is also never collapsed away.
  std::vector<char> pinned;
  // [key][vertex]: a boundary vertex on a corner of that key's outline, which does not slide in
  // that key and is never collapsed away; or empty for none.
  std::vector<std::vector<char>> heldIn;
};

struct ComeshMesh {
  // Builds the working mesh. Without `boundary`, every boundary vertex stays where it is.
  ComeshMesh(const Multimesh& mesh, const ComeshBoundary* boundary);

  // The result as a Multimesh: vertices left without triangles by collapses are dropped, and the
  // cohesive pairs C_i and boundary sets B_i are renumbered.
  Multimesh toMultimesh() const;

  int vertexCount() const { return static_cast<int>(around.size()); }
  int keyCount() const { return static_cast<int>(keys.size()); }
  bool onBoundary(int v) const { return arc[v] >= 0; }
  // Slides in key k: a boundary vertex past its arc's start, on an arc that is not a closed cut side in k.
  bool slides(int v, int k) const;
  // The triangle holding directed edge a -> b (counter-clockwise), or -1.
  int triangleWith(int a, int b) const;
  // The third corner of triangle t opposite edge (a, b).
  int thirdCorner(int t, int a, int b) const;
  // The edge's partner across a cut (the other side, collocated where the cut is closed), or {-1, -1}.
  std::array<int, 2> cutPartner(int a, int b) const;

  // Replaces edge (a, b) of triangles (a, b, c) and (b, a, d) by (c, d).
  void flip(int a, int b);
  // Inserts vertex v (already appended with addVertex) on edge (a, b), splitting its one or two
  // triangles; on a boundary edge, v joins the boundary walk between a and b.
  void split(int a, int b, int v);
  // After splitting cut edge (a, b) at v and its partner (c, d) at w (a with c, b with d): every
  // cohesive pair of the two edges becomes the two pairs of their halves.
  void splitPairs(int a, int b, int v, int c, int d, int w);
  // Moves vertex `from` onto `to`: triangles holding both disappear, `from` is left without
  // triangles (and, for a boundary edge, leaves the boundary walk).
  void collapse(int from, int to);
  // Appends a vertex with the given position in every key; returns its index.
  int addVertex(const std::vector<Eigen::Vector2d>& positions);
  // Drops the triangles emptied by collapses and rebuilds the incidence lists.
  void compact();

  std::vector<Triangle> triangles;            // counter-clockwise in every key; {-1,-1,-1} once deleted
  std::vector<double> kappa;                  // [triangle]: stiffness
  std::vector<Eigen::MatrixX2d> keys;         // [key]: positions, vertexCount() x 2
  std::vector<std::vector<int>> around;       // [vertex]: triangles holding it
  std::vector<int> arc;                       // [vertex]: boundary arc, -1 inside
  Eigen::MatrixXd u;                          // vertexCount() x keys: fraction along the arc, per key
  std::vector<int> next, previous;            // [vertex]: neighbours along the boundary walk, -1 inside
  std::vector<std::vector<char>> closedIn;    // [arc][key]
  std::function<Eigen::Vector2d(int, int, double)> point;
  std::function<double(int, int, double, double, double)> chordDeviation;
  std::function<double(int, int)> arcLength;
  std::vector<std::vector<CohesivePair>> cohesive;  // [key]: C_i
  std::vector<std::vector<char>> outline;           // [key][vertex]: in B_i
  std::vector<char> fixed;                    // [vertex]: never moves (all boundary vertices without `boundary`)
  std::vector<std::vector<char>> held;        // [key][vertex]: does not slide in that key (an outline corner there)
  long topologyVersion = 0;                   // counts changes of the triangle list: flips, splits, collapses, compact()
  long vertexSetVersion = 0;                  // counts splits and collapses (vertices added or emptied)

 private:
  void setTriangle(int t, const Triangle& corners);
  void detach(int t);
};

}  // namespace ib
