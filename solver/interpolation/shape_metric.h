// How each triangle's keys are averaged (docs/solver.md, "The shape metric";
// ../shared/shape-averaging.md explains the choice).
#pragma once

namespace ib {

// kPerKey: the paper's eq. 9. Key i's term measures the triangle in key i's own metric
// M_i = a_i B_i B_i^T, so a direction that one key stretches by k counts 1/k in that key's term,
// and the average length along it is the harmonic mean of the keys' lengths, not the arithmetic
// one: inbetweens shrink under stretch (36% at k = 4) and snap into the stretched key.
// kShared: every key's term uses one metric per triangle, the weights' blend
// M(w) = sum_i w_i M_i. With rotations fixed, the average is then the arithmetic mean of the rotated
// key triangles: no shrinking, even speed. The global matrix is the same (its metric is M(w) in
// both forms) and w = e_i reproduces key i exactly in both.
enum class ShapeMetric { kShared, kPerKey };

}  // namespace ib
