#include "render_fixtures.h"

#include "testkit/shape_generators.h"

namespace ib::test {

RgbaImage paintedImage(int width, int height, const std::function<std::array<uint8_t, 4>(int x, int y)>& colour) {
  RgbaImage image;
  image.width = width;
  image.height = height;
  image.hasAlpha = true;
  image.pixels.resize(static_cast<size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::array<uint8_t, 4> c = colour(x, y);
      std::copy(c.begin(), c.end(), image.at(x, y));
    }
  return image;
}

Multimesh squareGrid(int n, double x0, double y0, double side, int keys) {
  const GridMesh grid = rectangleGrid(n, n, side, side);
  Multimesh mesh(static_cast<int>(grid.points.rows()), grid.triangles);
  Eigen::MatrixX2d points = grid.points;
  points.col(0).array() += x0;
  points.col(1).array() += y0;
  for (int k = 0; k < keys; ++k) mesh.addKey(points, {}, grid.boundary);
  return mesh;
}

render::FrameDraw frameOf(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w, render::ViewBox view) {
  render::FrameDraw frame;
  frame.positions = &x;
  frame.weights = w;
  frame.view = view;
  return frame;
}

std::array<double, 4> pixel(const RgbaImage& image, int x, int y) {
  const uint8_t* p = image.at(x, y);
  return {double(p[0]), double(p[1]), double(p[2]), double(p[3])};
}

double coveredArea(const RgbaImage& image) {
  double sum = 0;
  for (size_t p = 3; p < image.pixels.size(); p += 4) sum += image.pixels[p] / 255.0;
  return sum;
}

CutSquare cutSquare() {
  const GridMesh half = rectangleGrid(5, 9, 16, 32);  // 4-pixel cells
  const int n = static_cast<int>(half.points.rows());
  std::vector<Triangle> triangles = half.triangles;
  for (Triangle t : half.triangles) {
    for (int& v : t) v += n;
    triangles.push_back(t);
  }
  Eigen::MatrixX2d glued(2 * n, 2);
  glued.topRows(n) = half.points;
  glued.bottomRows(n) = half.points;
  glued.col(0).head(n).array() += 8;
  glued.col(0).tail(n).array() += 24;
  Eigen::MatrixX2d open = glued;
  open.col(0).tail(n).array() += 8;
  CutSquare out{Multimesh(2 * n, triangles), {}, {}};
  for (int v = 0; v < n; ++v)
    if (half.points(v, 0) == 16) out.left.push_back(v);
    else if (half.points(v, 0) == 0) out.right.push_back(v + n);
  std::vector<CohesivePair> pairs;
  for (size_t j = 0; j + 1 < out.left.size(); ++j)
    pairs.push_back({out.left[j], out.left[j + 1], out.right[j], out.right[j + 1]});
  out.mesh.addKey(glued, pairs, {});
  out.mesh.addKey(open, {}, {});
  out.mesh.validate();
  return out;
}

std::vector<RgbaImage> cutSquareArtwork() {
  return {paintedImage(48, 32, [](int, int) { return std::array<uint8_t, 4>{20, 150, 140, 255}; }),
          paintedImage(48, 32, [](int x, int) { return x >= 24 && x < 32 ? std::array<uint8_t, 4>{0, 0, 0, 0} : std::array<uint8_t, 4>{240, 120, 20, 255}; })};
}

Eigen::MatrixX2d shiftedRight(const Eigen::MatrixX2d& x, const std::vector<int>& vertices, double dx) {
  Eigen::MatrixX2d out = x;
  for (int v : vertices) out(v, 0) += dx;
  return out;
}

}  // namespace ib::test
