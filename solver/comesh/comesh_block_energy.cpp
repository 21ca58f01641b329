#include "comesh/comesh_block_energy.h"

#include "core/thread_block.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <limits>

namespace ib {

void BlockEnergy::prepareRange(int begin, int end, const std::vector<Eigen::MatrixX2d>& keys) {
  const int m = static_cast<int>(keys.size());
  if (m < 2) {  // ODT alone
    for (auto* v : {&s00_, &s01_, &s11_, &q00_, &q01_, &q11_}) std::fill(v->begin() + begin, v->begin() + end, 0.0);
    std::fill(inverted_.begin() + begin, inverted_.begin() + end, 0);
    return;
  }
  // With two keys, next and previous are the same key: both directions of its map.
  const Eigen::MatrixX2d& next = keys[(key_ + 1) % m];
  const Eigen::MatrixX2d& previous = keys[(key_ + m - 1) % m];
  const double* nx = next.col(0).data();
  const double* ny = next.col(1).data();
  const double* px = previous.col(0).data();
  const double* py = previous.col(1).data();
  const int* c0 = corner_[0].data();
  const int* c1 = corner_[1].data();
  const int* c2 = corner_[2].data();
  double* s00 = s00_.data();
  double* s01 = s01_.data();
  double* s11 = s11_.data();
  double* q00 = q00_.data();
  double* q01 = q01_.data();
  double* q11 = q11_.data();
  char* inverted = inverted_.data();
  // One pass with gathers and selects, which GCC vectorizes (the outputs alias no input); entries
  // (r, c) of the 2 x 2 edge matrices are coordinate r of edge c.
#if defined(__clang__)
#pragma clang loop vectorize(assume_safety)
#else
#pragma GCC ivdep
#endif
  for (int k = begin; k < end; ++k) {
    const double n00 = nx[c1[k]] - nx[c0[k]], n01 = nx[c2[k]] - nx[c0[k]];
    const double n10 = ny[c1[k]] - ny[c0[k]], n11 = ny[c2[k]] - ny[c0[k]];
    const double nextArea = 0.5 * (n00 * n11 - n01 * n10);
    const bool positive = nextArea > 0;
    const double scale = positive ? 4 * nextArea : 1.0;
    s00[k] = positive ? (n00 * n00 + n10 * n10) / scale : 0.0;  // S = N^T N / (4 a_next)
    s01[k] = positive ? (n00 * n01 + n10 * n11) / scale : 0.0;
    s11[k] = positive ? (n01 * n01 + n11 * n11) / scale : 0.0;
    inverted[k] = !positive;
    const double p00 = px[c1[k]] - px[c0[k]], p01 = px[c2[k]] - px[c0[k]];
    const double p10 = py[c1[k]] - py[c0[k]], p11 = py[c2[k]] - py[c0[k]];
    q00[k] = p11 * p11 + p01 * p01;  // Q = adj(P) adj(P)^T, adj(P) = [p11 -p01; -p10 p00]
    q01[k] = -p11 * p10 - p01 * p00;
    q11[k] = p10 * p10 + p00 * p00;
  }
}

void BlockEnergy::prepare(const std::vector<Triangle>& triangles, const std::vector<Eigen::MatrixX2d>& keys, int i,
                          double odtWeight) {
  key_ = i;
  odtWeight_ = odtWeight;
  count_ = 0;
  for (const Triangle& tri : triangles) count_ += tri[0] >= 0;
  for (auto& c : corner_) c.resize(count_);
  for (auto* v : {&s00_, &s01_, &s11_, &q00_, &q01_, &q11_}) v->resize(count_);
  inverted_.resize(count_);
  int k = 0;
  for (const Triangle& tri : triangles) {
    if (tri[0] < 0) continue;
    for (int c = 0; c < 3; ++c) corner_[c][k] = tri[c];
    ++k;
  }
  prepareRange(0, count_, keys);
  neighbourInverted_ = std::find(inverted_.begin(), inverted_.end(), 1) != inverted_.end();
}

void BlockEnergy::update(const std::vector<Triangle>& triangles, const std::vector<Eigen::MatrixX2d>& keys) {
  const bool sameList = static_cast<int>(triangles.size()) == count_ &&
                        std::none_of(triangles.begin(), triangles.end(), [](const Triangle& t) { return t[0] < 0; });
  if (!sameList) return prepare(triangles, keys, key_, odtWeight_);
  for (int k = 0; k < count_; ++k) {
    const Triangle& tri = triangles[k];
    if (tri[0] == corner_[0][k] && tri[1] == corner_[1][k] && tri[2] == corner_[2][k]) continue;
    for (int c = 0; c < 3; ++c) corner_[c][k] = tri[c];
    prepareRange(k, k + 1, keys);
  }
  neighbourInverted_ = std::find(inverted_.begin(), inverted_.end(), 1) != inverted_.end();
}

double BlockEnergy::evaluate(const Eigen::MatrixX2d& x, Eigen::MatrixX2d* gradient) const {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  if (neighbourInverted_) return kInfinity;
  const int t = count_;
  if (scratch_.size() != 12 * t) scratch_.resize(12 * t);  // no zero fill: every entry read is written first
  // Per triangle: the edge matrix E, the unscaled ODT gradient and the MIPS gradient (each 2 x 2,
  // row = coordinate, column = edge).
  double* E00 = scratch_.data();
  double* E01 = E00 + t;
  double* E10 = E01 + t;
  double* E11 = E10 + t;
  double* O00 = E11 + t;
  double* O01 = O00 + t;
  double* O10 = O01 + t;
  double* O11 = O10 + t;
  double* M00 = O11 + t;
  double* M01 = M00 + t;
  double* M10 = M01 + t;
  double* M11 = M10 + t;
  const double* px = x.col(0).data();
  const double* py = x.col(1).data();
  const int* c0 = corner_[0].data();
  const int* c1 = corner_[1].data();
  const int* c2 = corner_[2].data();
  const bool wantGradient = gradient != nullptr;
  // Each block of triangles sums its own terms; the sums are added in block order afterwards, so
  // the energy is bit-identical from run to run, whatever the team (thread_block.h).
  const int blocks = t >= kParallelTriangles ? threads_ : 1;
  std::vector<std::array<double, 4>> partial(static_cast<size_t>(blocks));  // odt, area, mips, smallest
#pragma omp parallel num_threads(teamFor(blocks))
  for (int p = omp_get_thread_num(); p < blocks; p += omp_get_num_threads()) {
    const int begin = static_cast<int>(static_cast<long>(t) * p / blocks);
    const int end = static_cast<int>(static_cast<long>(t) * (p + 1) / blocks);
    double odt = 0, area = 0, mips = 0, smallest = kInfinity;
#pragma omp simd reduction(+ : odt, area, mips) reduction(min : smallest)
    for (int k = begin; k < end; ++k) {
      const double e00 = px[c1[k]] - px[c0[k]], e01 = px[c2[k]] - px[c0[k]];
      const double e10 = py[c1[k]] - py[c0[k]], e11 = py[c2[k]] - py[c0[k]];
      const double a = 0.5 * (e00 * e11 - e01 * e10);
      smallest = std::min(smallest, a);
      // ODT (eq. 4): a / 12 times the squared edge lengths, the third edge e1 - e0 = (t0, t1).
      const double t0 = e01 - e00, t1 = e11 - e10;
      const double squares = e00 * e00 + e10 * e10 + e01 * e01 + e11 * e11 + t0 * t0 + t1 * t1;
      odt += a * squares / 12;
      area += a;
      // MIPS towards next: adj(E) has columns (e11, -e10) and (-e01, e00).
      const double s00 = s00_[k], s01 = s01_[k], s11 = s11_[k];
      const double d0x = s00 * e11 - s01 * e10, d0y = s01 * e11 - s11 * e10;  // S adj(E) e_0
      const double d1x = -s00 * e01 + s01 * e00, d1y = -s01 * e01 + s11 * e00;  // S adj(E) e_1
      const double toNext = e11 * d0x - e10 * d0y - e01 * d1x + e00 * d1y;
      // MIPS from previous: tr(E Q E^T) / (4a), with E's rows (e00, e01) and (e10, e11).
      const double q00 = q00_[k], q01 = q01_[k], q11 = q11_[k];
      const double r00 = q00 * e00 + q01 * e01, r01 = q01 * e00 + q11 * e01;  // (E Q) row 0
      const double r10 = q00 * e10 + q01 * e11, r11 = q01 * e10 + q11 * e11;  // (E Q) row 1
      const double fromPrevious = (e00 * r00 + e01 * r01 + e10 * r10 + e11 * r11) / (4 * a);
      mips += toNext + fromPrevious;
      if (wantGradient) {
        E00[k] = e00;
        E01[k] = e01;
        E10[k] = e10;
        E11[k] = e11;
        // d squares / dE: columns 2 e0 - 2 (e1 - e0) and 2 e1 + 2 (e1 - e0); d a / dE = cof(E) / 2.
        const double half = 0.5 * squares;
        O00[k] = (half * e11 + a * (2 * e00 - 2 * t0)) / 12;
        O01[k] = (-half * e10 + a * (2 * e01 + 2 * t0)) / 12;
        O10[k] = (-half * e01 + a * (2 * e10 - 2 * t1)) / 12;
        O11[k] = (half * e00 + a * (2 * e11 + 2 * t1)) / 12;
        // toNext: d/d adj(E) = 2 S adj(E), taken back through adj's entry map. fromPrevious:
        // 2 E Q / (4a) - fromPrevious / a * cof(E) / 2.
        const double over = 1 / (2 * a), shrink = fromPrevious * over;
        M00[k] = 2 * d1y + r00 * over - shrink * e11;
        M01[k] = -2 * d1x + r01 * over + shrink * e10;
        M10[k] = -2 * d0y + r10 * over + shrink * e01;
        M11[k] = 2 * d0x + r11 * over - shrink * e00;
      }
    }
    partial[static_cast<size_t>(p)] = {odt, area, mips, smallest};
  }
  double odt = 0, area = 0, mips = 0, smallest = kInfinity;
  for (const auto& p : partial) {
    odt += p[0];
    area += p[1];
    mips += p[2];
    smallest = std::min(smallest, p[3]);
  }
  if (!(smallest > 0)) return kInfinity;
  const double energy = odtWeight_ * odt / area + mips;
  if (!wantGradient) return energy;
  // ODT / area by the quotient rule: (w / A) d odt - (w odt / A^2) d A, with d A = cof(E) / 2.
  const double alpha = odtWeight_ / area, beta = -0.5 * odtWeight_ * odt / (area * area);
  gradient->setZero(x.rows(), 2);
  double* gx = gradient->col(0).data();
  double* gy = gradient->col(1).data();
  for (int k = 0; k < t; ++k) {
    const double g00 = alpha * O00[k] + beta * E11[k] + M00[k];
    const double g01 = alpha * O01[k] - beta * E10[k] + M01[k];
    const double g10 = alpha * O10[k] - beta * E01[k] + M10[k];
    const double g11 = alpha * O11[k] + beta * E00[k] + M11[k];
    gx[c1[k]] += g00;
    gy[c1[k]] += g10;
    gx[c2[k]] += g01;
    gy[c2[k]] += g11;
    gx[c0[k]] -= g00 + g01;
    gy[c0[k]] -= g10 + g11;
  }
  return energy;
}

}  // namespace ib
