#include "meshing/conforming_mesh.h"

#include "core/error.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <map>
#include <queue>
#include <set>

namespace ib {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
struct VertexInfo {
  int id = -1;  // input point index; -1 for points the mesher adds
};
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, Kernel>;
using FaceBase = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Mesher = CGAL::Delaunay_mesher_2<Cdt, Criteria>;

std::pair<int, int> key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// Marks the faces enclosed by an odd number of boundary segments as in the domain, by a flood
// fill from the infinite face that flips at boundary constraints and not at cut constraints.
void markDomain(Cdt& cdt, const std::set<std::pair<int, int>>& boundary) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->set_in_domain(false);
  std::map<Cdt::Face_handle, bool> seen;
  std::queue<std::pair<Cdt::Face_handle, bool>> queue;
  queue.push({cdt.infinite_face(), false});
  seen[cdt.infinite_face()] = true;
  while (!queue.empty()) {
    const auto [face, inside] = queue.front();
    queue.pop();
    if (!cdt.is_infinite(face)) face->set_in_domain(inside);
    for (int i = 0; i < 3; ++i) {
      const Cdt::Face_handle next = face->neighbor(i);
      if (seen.count(next)) continue;
      seen[next] = true;
      const int a = face->vertex(Cdt::cw(i))->info().id, b = face->vertex(Cdt::ccw(i))->info().id;
      const bool flips = face->is_constrained(i) && a >= 0 && b >= 0 && boundary.count(key(a, b));
      queue.push({next, inside != flips});
    }
  }
}

}  // namespace

ConformingMesh conformingMesh(const std::vector<Eigen::Vector2d>& points,
                              const std::vector<std::array<int, 2>>& boundary,
                              const std::vector<std::array<int, 2>>& cuts, const ConformingMeshOptions& options) {
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles;
  for (size_t i = 0; i < points.size(); ++i) {
    handles.push_back(cdt.insert(Kernel::Point_2(points[i].x(), points[i].y())));
    if (handles.back()->info().id >= 0 && handles.back()->info().id != static_cast<int>(i))
      throw InputError("the outline passes twice through the point (" + std::to_string(points[i].x()) + ", " +
                       std::to_string(points[i].y()) + ")");
    handles.back()->info().id = static_cast<int>(i);
  }
  std::set<std::pair<int, int>> boundaryKeys;
  for (const auto& s : boundary) {
    cdt.insert_constraint(handles[s[0]], handles[s[1]]);
    boundaryKeys.insert(key(s[0], s[1]));
  }
  for (const auto& s : cuts) cdt.insert_constraint(handles[s[0]], handles[s[1]]);
  markDomain(cdt, boundaryKeys);

  Mesher mesher(cdt, Criteria(options.shapeBound, options.maxEdgeLength));
  mesher.init(true);
  while (!mesher.is_refinement_done()) {
    mesher.step_by_step_refine_mesh();
    if (static_cast<int>(cdt.number_of_vertices()) > options.maxVertices)
      throw InputError("meshing needs more than " + std::to_string(options.maxVertices) +
                       " vertices; the shape has features too fine for the edge length");
  }

  ConformingMesh out;
  out.points = points;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (v->info().id < 0) {
      v->info().id = static_cast<int>(out.points.size());
      out.points.emplace_back(v->point().x(), v->point().y());
    }
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    out.triangles.push_back({f->vertex(0)->info().id, f->vertex(1)->info().id, f->vertex(2)->info().id});
    for (int i = 0; i < 3; ++i) {
      const Cdt::Face_handle other = f->neighbor(i);
      const int a = f->vertex(Cdt::cw(i))->info().id, b = f->vertex(Cdt::ccw(i))->info().id;
      if (f->is_constrained(i) && !cdt.is_infinite(other) && other->is_in_domain() && a < b) out.cuts.push_back({a, b});
    }
  }
  return out;
}

}  // namespace ib
