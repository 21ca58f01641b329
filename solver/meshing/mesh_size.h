// How fine the multimesh is, decided before it is built: the default edge length, which follows
// the drawings' size (docs/drawings-to-multimesh.md, "Edge length"), and the size guard, which
// estimates the mesh from the traced shapes and refuses one past the scene's `max_vertices` before
// any heavy work (meshing, mapping, Comesh).
#pragma once

#include "meshing/tracing.h"

#include <string>
#include <vector>

namespace ib {

struct Scene;  // scene/scene.h

// The default edge length's rule: sqrt(mean key area) / kEdgeDivisions, clamped to
// [kMinDefaultEdge, kMaxDefaultEdge] px. A sprite of 32-128 px then gets about 16 edges across
// its shape (a few hundred vertices, outlines within about a pixel of the drawing); drawings of
// 256 px and more keep 8 px, the default before the rule.
constexpr double kEdgeDivisions = 16;
constexpr double kMinDefaultEdge = 1;  // px: finer than a pixel only resolves potrace's curves
constexpr double kMaxDefaultEdge = 8;  // px

// Area of a traced drawing: outer loops minus holes, px^2.
double tracedArea(const std::vector<Outline>& outlines);
// Length of every loop of a traced drawing, px.
double tracedPerimeter(const std::vector<Outline>& outlines);

// [key]: traced drawings -> the default edge length, px (the rule above).
double defaultEdgeLength(const std::vector<std::vector<Outline>>& outlines);

// Vertices of the multimesh meshed at `edgeLength` from a reference shape of `area` px^2 and
// `perimeter` px, before Comesh: kInteriorDensity * area / e^2 + perimeter / e. CGAL's triangles
// keep every edge under e, so they are smaller than equilateral ones of side e (which would give
// 1.15 area / e^2): measured, 2.5 area / e^2 for the interior, on a disc and a bird sprite at
// 96-512 px from 700 to 100k vertices, every build within 10% of the estimate
// (tests/test_mesh_size.cpp checks it).
constexpr double kInteriorDensity = 2.5;
double estimateVertices(double area, double perimeter, double edgeLength);

// The edge length a build starts from, px: the scene's `edge_length` when it sets one, else
// defaultEdgeLength, raised if need be so that the default never trips the guard (a drawing of
// thousands of pixels gets the edge length that fits max_vertices). Then the size guard: throws
// InputError naming the scene file, the estimate, the limit and what to do (a larger
// `edge_length`, or `max_vertices` raised) when the reference key's traced shape at that edge
// length would give more than scene.maxVertices vertices.
double meshEdgeLength(const Scene& scene, const std::vector<std::vector<Outline>>& outlines);

// "about 38,000 vertices": the estimate for a reference key's traced shape, for progress lines.
std::string estimatedSize(const std::vector<Outline>& reference, double edgeLength);

// Whether a build at `edgeLength` stays within scene.maxVertices (for the finer retries after a
// fold): the estimate for the reference key's traced shape.
bool withinMeshLimit(const Scene& scene, const std::vector<Outline>& reference, double edgeLength);

}  // namespace ib
