// `inbetween mesh` on the generated example scenes that build: the multimesh files and pictures it
// writes (and the folders it creates for them), the --json summary, with Comesh Optimization's
// statistics and the quality before and after, and the notes on stderr for odd but accepted input.
#include "cli_support.h"

#include <catch2/catch.hpp>
#include <string>

using Catch::Matches;
using Catch::StartsWith;
using test::CommandRun;
using test::exampleScene;
using test::exists;
using test::inbetween;
using test::scratchPath;
using Json = nlohmann::json;

namespace {

// The --json summary of a run that must succeed silently.
Json meshSummary(const std::vector<std::string>& args) {
  const CommandRun run = inbetween(args);
  INFO(run.output);
  REQUIRE(run.code == 0);
  CHECK(run.err.empty());
  REQUIRE(Json::accept(run.out));
  return Json::parse(run.out);
}

}  // namespace

TEST_CASE("cli: mesh builds square-arch-notch and prints JSON") {
  const std::string scene = exampleScene("square-arch-notch");
  const std::string out = scratchPath("notch/out.ibmesh");
  const Json summary = meshSummary({"mesh", scene, "--json", "-o", out});
  INFO(summary.dump());
  CHECK(summary.at("scene") == scene);
  CHECK(summary.at("edge_length") == 6.0);
  CHECK(summary.at("initial").at("vertices").get<int>() > 0);
  CHECK(summary.at("initial").at("keys").size() == 2);
  CHECK(summary.at("initial").at("keys").at(0).at("name") == "square");
  CHECK(summary.at("initial").at("keys").at(1).at("name") == "arch");
  CHECK(summary.at("initial").at("multimesh") == scratchPath("notch/out.initial.ibmesh"));
  CHECK(summary.at("optimized").at("multimesh") == out);
  CHECK(summary.at("comesh").at("inner").get<int>() > 0);
  CHECK(summary.at("optimized").at("maps").at(0).at("mips_mean").get<double>() >= 2);
  CHECK(exists(out));
  CHECK(exists(scratchPath("notch/out.initial.ibmesh")));
}

TEST_CASE("cli: mesh runs Comesh on pentagon-star and reports before and after") {
  const std::string out = scratchPath("pentagon-star/out.ibmesh");
  const Json summary = meshSummary({"mesh", exampleScene("pentagon-star"), "--json", "-o", out});
  INFO(summary.dump());
  const Json& comesh = summary.at("comesh");
  CHECK(comesh.at("keys") == 2);
  CHECK(comesh.at("inner").get<int>() > 0);
  CHECK(comesh.at("outer").get<int>() > 0);
  CHECK(comesh.at("vertices_in") == summary.at("initial").at("vertices"));
  CHECK(comesh.at("vertices_out") == summary.at("optimized").at("vertices"));
  // The quality of both maps (polygon -> star, star -> polygon), before and after.
  for (const char* version : {"initial", "optimized"}) {
    const Json& maps = summary.at(version).at("maps");
    REQUIRE(maps.size() == 2);
    CHECK(maps.at(0).at("from") == "polygon");
    CHECK(maps.at(0).at("to") == "star");
    CHECK(maps.at(0).at("mips_mean").get<double>() >= 2);  // 2 is conformal, the least there is
  }
}

TEST_CASE("cli: mesh --no-comesh builds the initial map only") {
  const std::string out = scratchPath("pentagon-star/initial-only.ibmesh");
  const Json summary = meshSummary({"mesh", exampleScene("pentagon-star"), "--json", "--no-comesh", "-o", out});
  INFO(summary.dump());
  CHECK(summary.at("initial").at("vertices").get<int>() > 0);
  CHECK(summary.at("initial").at("multimesh") == out);
  CHECK_FALSE(summary.contains("comesh"));
  CHECK_FALSE(summary.contains("optimized"));
  CHECK(exists(out));
  CHECK_FALSE(exists(scratchPath("pentagon-star/initial-only.initial.ibmesh")));
}

TEST_CASE("cli: mesh -o into a folder that does not exist creates it") {
  REQUIRE_FALSE(exists(scratchPath("mesh-new-folder")));
  const CommandRun run = inbetween({"mesh", exampleScene("square-arch-notch"), "-o", scratchPath("mesh-new-folder/deep/out.ibmesh"), "--no-pictures"});
  INFO(run.output);
  CHECK(run.code == 0);
  CHECK(exists(scratchPath("mesh-new-folder/deep/out.ibmesh")));
  CHECK(exists(scratchPath("mesh-new-folder/deep/out.initial.ibmesh")));
}

TEST_CASE("cli: mesh pictures the initial map as NAME.initial.KEY.svg and names them in --json") {
  const std::string pictures = scratchPath("pentagon-star/pictures");
  const Json summary = meshSummary({"mesh", exampleScene("pentagon-star"), "--json", "-o", pictures + ".ibmesh"});
  INFO(summary.dump());
  CHECK(summary.at("initial").at("keys").at(0).at("picture") == pictures + ".initial.polygon.svg");
  CHECK(summary.at("initial").at("keys").at(1).at("picture") == pictures + ".initial.star.svg");
  CHECK(summary.at("optimized").at("keys").at(0).at("picture") == pictures + ".polygon.svg");
  CHECK(summary.at("optimized").at("keys").at(1).at("picture") == pictures + ".star.svg");
  for (const char* suffix : {".initial.polygon.svg", ".initial.star.svg", ".polygon.svg", ".star.svg"}) {
    INFO(suffix);
    CHECK(exists(pictures + suffix));
  }
}

TEST_CASE("cli: mesh --no-comesh pictures the initial map as NAME.KEY.svg") {
  const std::string pictures = scratchPath("pentagon-star/initial-pictures");
  const Json summary = meshSummary({"mesh", exampleScene("pentagon-star"), "--json", "--no-comesh", "-o", pictures + ".ibmesh"});
  INFO(summary.dump());
  CHECK(summary.at("initial").at("keys").at(0).at("picture") == pictures + ".polygon.svg");
  CHECK(summary.at("initial").at("keys").at(1).at("picture") == pictures + ".star.svg");
  CHECK(exists(pictures + ".polygon.svg"));
  CHECK(exists(pictures + ".star.svg"));
  CHECK_FALSE(exists(pictures + ".initial.polygon.svg"));
}

TEST_CASE("cli: mesh on a scene with nothing odd prints no note") {
  const CommandRun run = inbetween({"mesh", exampleScene("square-arch-notch"), "-o", scratchPath("quiet/quiet.ibmesh"), "--no-pictures", "--no-comesh"});
  INFO(run.output);
  CHECK(run.code == 0);
  CHECK(run.err.empty());  // no note, nor anything else
}

TEST_CASE("cli: mesh with keys on canvases of different sizes exits 0 with a note") {
  const CommandRun run = inbetween({"mesh", test::badScene("canvas-sizes.json"), "-o", scratchPath("canvas-sizes/out.ibmesh"), "--no-pictures"});
  INFO(run.output);
  CHECK(run.code == 0);
  CHECK_THAT(run.err, Matches(R"(inbetween: note: canvas-sizes\.json: keys have different canvas sizes \(128x128 for "square", 140x128 for "other"\): )"
                              R"(positions are drawing pixels from each drawing's top-left.*the renderer's canvas is the largest, 140x128.*\n)"));
  CHECK(exists(scratchPath("canvas-sizes/out.ibmesh")));
}

TEST_CASE("cli: mesh with one key exits 0 with a note that the animation is a still") {
  const CommandRun run = inbetween({"mesh", test::badScene("one-key.json"), "-o", scratchPath("one-key/out.ibmesh"), "--no-pictures"});
  INFO(run.output);
  CHECK(run.code == 0);
  CHECK_THAT(run.err, StartsWith("inbetween: note: one-key.json: one key (\"square\"): the animation is a still"));
  CHECK(exists(scratchPath("one-key/out.ibmesh")));
}

TEST_CASE("cli: mesh notes a key Comesh left under 10 degrees, and what to do") {
  const CommandRun run = inbetween({"mesh", exampleScene("pentagon-star-thin"), "-o", scratchPath("thin/noted.ibmesh"), "--no-pictures"});
  INFO(run.output);
  CHECK(run.code == 0);
  CHECK_THAT(run.err, Matches(R"(inbetween: note: scene\.json: Comesh Optimization left key "polygon"'s smallest angle [0-9.]+ -> [0-9.]+ deg )"
                              R"(\(under 10 deg, or above 20, where the initial map was not\): a sliver.*--no-comesh.*"edge_length".*\n)"));
}

TEST_CASE("cli: mesh --suggest lists the cat's corners the shape matching pairs: the body's where every key has "
          "them, sure; printed in the scene's key order") {
  const std::string scene = std::string(INBETWEEN_SOURCE_DIR) + "/tests/correspondence/cat-tail/scene.json";
  const Json summary = meshSummary({"mesh", scene, "--json", "--suggest", "--no-pictures", "-o", scratchPath("suggest/cat.ibmesh")});
  const Json& suggestions = summary.at("suggestions");
  REQUIRE(suggestions.size() >= 5);
  int still = 0;
  double previous = 1;
  for (const Json& s : suggestions) {
    INFO(s.dump());
    const double confidence = s.at("confidence").get<double>();
    CHECK(confidence <= previous);  // surest first
    CHECK(confidence >= 0.3);
    previous = confidence;
    CHECK(s.at("at").size() == 3);
    CHECK(s.at("name").get<std::string>().rfind("s", 0) == 0);
    // The head and body are the same drawing in every key: their corners are paired in place, sure.
    if (s.at("moved").get<double>() < 0.5) still += confidence >= 0.85;
  }
  CHECK(still >= 5);
  const CommandRun text = inbetween({"mesh", scene, "--suggest", "--no-pictures", "-o", scratchPath("suggest/cat2.ibmesh")});
  REQUIRE(text.code == 0);
  CHECK_THAT(text.out, Catch::Contains("suggested features: ") && Matches("(.|\n)*s1 +confidence 1.00 +moved +0.0 px +down \\(.*\\) out \\(.*\\) up \\((.|\n)*"));
}
