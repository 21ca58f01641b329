// Placement: ARAP, cohesive and non-overlap energies do not see where a shape is, only its
// form, so a rigid motion of any independently moving group of vertices is free. The solver
// fixes it with a weak tie to the linear blend of the keys, Xbar(w) = sum_i w_i X_i:
//   E_P = mu/2 sum_v m_v |x_v - Xbar_v|^2     (sum_v m_v = 1 in normalized area units, mu small;
//                                              m_v = 1/n, or stillnessWeights for Placement::kStill)
// and, every iteration, moves each group by the rigid motion that minimizes E_P (Procrustes),
// which leaves the other energies unchanged. At w = e_i the minimizer is X_i
// itself, where it was drawn; inbetweens depend only on w, so they cannot drift.
#pragma once

#include "core/thread_block.h"

#include <Eigen/Core>
#include <utility>
#include <vector>

namespace ib {

// Groups of vertices that move rigidly together: connected components of the mesh edges plus
// extra links (held pairs, non-overlap contacts). Union-find, O(n alpha(n)).
class PlacementGroups {
 public:
  PlacementGroups(int vertexCount, const std::vector<std::pair<int, int>>& meshEdges);
  // Regroups with the extra links joined in (groups are numbered 0..groupCount()-1).
  void update(const std::vector<std::pair<int, int>>& links);
  int groupCount() const { return groupCount_; }
  int groupOf(int v) const { return label_[v]; }
  // Vertices of group k: members()[memberStart()[k] .. memberStart()[k + 1]).
  const std::vector<int>& memberStart() const { return memberStart_; }
  const std::vector<int>& members() const { return members_; }

 private:
  void buildMembers();
  std::vector<int> meshComponent_;  // component label from mesh edges alone
  int meshComponents_ = 0;
  std::vector<int> label_;  // group of each vertex
  int groupCount_ = 0;
  std::vector<int> memberStart_, members_;  // CSR lists of each group's vertices
};

// Applies, per group, the rigid motion (rotation + translation) minimizing
// sum_v m_v |R x_v + t - target_v|^2. x, target: n x 2; weights: m_v (n x 1), or empty for the
// same m_v for every vertex. rows: when given (rows.size() = n), a single group is aligned in
// parallel, thread p summing and moving the vertices [rows.begin(p), rows.end(p)); several
// groups are aligned serially.
void alignGroups(Eigen::MatrixX2d& x, const Eigen::MatrixX2d& target, const PlacementGroups& groups,
                 const RowSplit& rows = {}, const Eigen::VectorXd& weights = {});

// Placement::kStill's m_v (n x 1, summing to 1): 1 + kStillWeight exp(-(d_v / kStillRadius)^2),
// d_v the largest distance of vertex v in any key from its place in key 0, in pixels. keys:
// X_i (n x 2, any unit), pixel: one drawing pixel in that unit. A vertex drawn at the same place
// in every key weighs 100 times one that moves; where nothing stays, every vertex weighs alike.
constexpr double kStillWeight = 99;
constexpr double kStillRadius = 1.0;  // pixels
Eigen::VectorXd stillnessWeights(const std::vector<Eigen::MatrixX2d>& keys, double pixel);

}  // namespace ib
