#include "render_fixtures.h"

#include "shape_generators.h"

namespace ib::test {

vk::VulkanContext validatedContext() {
  vk::ContextOptions options;
  options.validation = true;
  options.device = vk::DevicePreference::kSoftware;
  return vk::VulkanContext(options);
}

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

}  // namespace ib::test
