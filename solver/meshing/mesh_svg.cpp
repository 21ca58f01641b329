#include "meshing/mesh_svg.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <vector>

namespace ib {

namespace {

std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const unsigned a = static_cast<unsigned char>(bytes[i]);
    const unsigned b = i + 1 < bytes.size() ? static_cast<unsigned char>(bytes[i + 1]) : 0;
    const unsigned c = i + 2 < bytes.size() ? static_cast<unsigned char>(bytes[i + 2]) : 0;
    const unsigned v = a << 16 | b << 8 | c;
    out += digits[v >> 18 & 63];
    out += digits[v >> 12 & 63];
    out += i + 1 < bytes.size() ? digits[v >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? digits[v & 63] : '=';
  }
  return out;
}

std::string escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

// Estimated advance of one character in em (see estimatedTextBox).
double advance(unsigned char c) {
  if (c >= 0x80) return 1.0;
  if (c != 0 && std::strchr("ijltfrIJ.,:;'!|()[]- ", c) != nullptr) return 0.4;
  if (c != 0 && std::strchr("mwMW@%", c) != nullptr) return 1.0;
  if (c >= 'A' && c <= 'Z') return 0.8;
  return 0.65;
}

}  // namespace

int svgScale(int width, int height) {
  const int larger = std::max(1, std::max(width, height));
  return std::clamp((kShownPixels + larger - 1) / larger, 1, 16);
}

TextBox estimatedTextBox(const std::string& text, double x, double y, double fontSize, bool anchorEnd) {
  double em = 0;
  for (unsigned char c : text)
    if ((c & 0xC0) != 0x80) em += advance(c);  // UTF-8 continuation bytes belong to the character before
  const double width = em * fontSize;
  return {anchorEnd ? x - width : x, y - 0.8 * fontSize, anchorEnd ? x : x + width, y + 0.25 * fontSize};
}

std::string meshSvg(const Multimesh& mesh, int key, const KeyShape& shape, const std::string& drawingPng, int width,
                    int height, const std::vector<InteriorMark>& interior) {
  const Eigen::MatrixX2d x = mesh.keyPositions(key);
  // Shown at a whole multiple of the drawing's size so that its larger side is at least
  // kShownPixels on screen (a 100 px sprite at 8x, its pixels crisp), with lines and labels sized
  // for the picture as shown: 1/1500 of the drawing, at least 0.15 screen px.
  const int scale = svgScale(width, height);
  const double stroke = std::max(0.15 / scale, std::max(width, height) / 1500.0);  // drawing px
  const double radius = 6 * stroke, font = 40 * stroke;
  // The dots and labels first, so the viewBox can take them in. Labels point away from the middle
  // of the mesh, so features on opposite sides do not collide.
  std::ostringstream features;
  features.precision(6);
  TextBox bounds{0, 0, double(width), double(height)};  // drawing px
  const auto include = [&bounds](const TextBox& b) {
    bounds = {std::min(bounds.x0, b.x0), std::min(bounds.y0, b.y0), std::max(bounds.x1, b.x1),
              std::max(bounds.y1, b.y1)};
  };
  const double middle = 0.5 * (x.col(0).minCoeff() + x.col(0).maxCoeff());
  std::vector<Eigen::Vector2d> labelled;  // features already drawn: collocated ones stack their labels
  const auto mark = [&](const std::string& name, const Eigen::Vector2d& p) {
    int below = 0;
    for (const Eigen::Vector2d& q : labelled) below += (q - p).norm() < radius;
    labelled.push_back(p);
    const bool left = p.x() < middle;
    const double tx = p.x() + (left ? -1.5 : 1.5) * radius, ty = p.y() - 1.5 * radius + 1.1 * font * below;
    include({p.x() - radius, p.y() - radius, p.x() + radius, p.y() + radius});
    include(estimatedTextBox(name, tx, ty, font, left));
    features << "<circle cx=\"" << p.x() << "\" cy=\"" << p.y() << "\" r=\"" << radius << "\" fill=\"#f0a000\"/>"
             << "<text text-anchor=\"" << (left ? "end" : "start") << "\" x=\"" << tx << "\" y=\"" << ty
             << "\" font-size=\"" << font << "\" font-family=\"sans-serif\" fill=\"#804000\">" << escaped(name)
             << "</text>\n";
  };
  for (const ShapeLoop& loop : shape.loops)
    for (size_t i = 0; i < loop.points.size(); ++i)
      if (!loop.features[i].empty()) mark(loop.features[i], loop.points[i]);
  for (const InteriorMark& m : interior) {
    if (m.radius > 0)
      features << "<circle cx=\"" << m.at.x() << "\" cy=\"" << m.at.y() << "\" r=\"" << m.radius
               << "\" fill=\"none\" stroke=\"#f0a000\" stroke-width=\"" << 2 * stroke << "\" stroke-dasharray=\""
               << 4 * stroke << "\"/>\n";
    mark(m.name, m.at);
  }
  // Whole pixels, one user unit a drawing pixel, shown `scale` screen pixels each.
  // (0.01 px of slack: a label's box computed again from its printed position may round outwards.)
  const long x0 = std::lround(std::floor(bounds.x0 - 0.01)), y0 = std::lround(std::floor(bounds.y0 - 0.01));
  const long w = std::lround(std::ceil(bounds.x1 + 0.01)) - x0, h = std::lround(std::ceil(bounds.y1 + 0.01)) - y0;
  std::ostringstream svg;
  svg.precision(6);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << x0 << ' ' << y0 << ' ' << w << ' ' << h
      << "\" width=\"" << w * scale << "\" height=\"" << h * scale << "\">\n";
  svg << "<image width=\"" << width << "\" height=\"" << height << "\" opacity=\"0.6\""
      << (scale > 1 ? " style=\"image-rendering:pixelated\"" : "") << " href=\"data:image/png;base64,"
      << base64(drawingPng) << "\"/>\n";
  svg << "<path fill=\"none\" stroke=\"#1f5fbf\" stroke-width=\"" << stroke << "\" stroke-linejoin=\"round\" d=\"";
  for (const Triangle& t : mesh.triangles())
    svg << 'M' << x(t[0], 0) << ',' << x(t[0], 1) << 'L' << x(t[1], 0) << ',' << x(t[1], 1) << 'L' << x(t[2], 0) << ','
        << x(t[2], 1) << 'Z';
  svg << "\"/>\n<path fill=\"none\" stroke=\"#e0201b\" stroke-width=\"" << 3 * stroke << "\" d=\"";
  for (const CohesivePair& p : mesh.cohesivePairs(key))
    svg << 'M' << x(p.a, 0) << ',' << x(p.a, 1) << 'L' << x(p.b, 0) << ',' << x(p.b, 1);
  svg << "\"/>\n" << features.str();
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace ib
