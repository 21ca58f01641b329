#include "comesh.h"
#include "comesh_energy.h"
#include "drawings.h"
#include "example_scenes.h"
#include "mesh_quality.h"
#include "multimesh_builder.h"

#include <catch2/catch.hpp>
#include <filesystem>

using namespace ib;

TEST_CASE("comesh: vertex steps lower the objective of eq. 8, keep every triangle positive and the boundary put") {
  const std::string folder = test::scratchDirectory("comesh");
  for (const auto& example : test::goodScenes()) {
    INFO("scene " << example.name);
    test::writeScene(example, folder);
    const Scene scene = loadScene((std::filesystem::path(folder) / example.name / "scene.json").string());
    Multimesh mesh = *buildMultimesh(scene, MultimeshBuildOptions{}).multimesh;
    std::vector<Eigen::MatrixX2d> start;
    for (int k = 0; k < mesh.keyCount(); ++k) start.push_back(mesh.keyPositions(k));
    const std::vector<Triangle> triangles = mesh.triangles();
    const std::vector<char> movable = interiorVertices(mesh);
    ComeshOptions options;
    options.outerIterations = 20;
    const ComeshReport report = comeshOptimize(mesh, movable, options);
    INFO("outer " << report.outerIterations << ", inner " << report.innerIterations << ", " << report.seconds << " s");
    CHECK_NOTHROW(mesh.validate());  // positive areas, collocated cohesive pairs
    std::vector<Eigen::MatrixX2d> end;
    for (int k = 0; k < mesh.keyCount(); ++k) end.push_back(mesh.keyPositions(k));
    CHECK(comeshEnergy(triangles, end) <= comeshEnergy(triangles, start));  // block descent is monotone
    for (int k = 0; k < mesh.keyCount(); ++k) {
      const Eigen::MatrixX2d x = mesh.keyPositions(k);
      for (int v = 0; v < mesh.vertexCount(); ++v)
        if (!movable[v]) REQUIRE(x.row(v) == start[k].row(v));
    }
  }
}
