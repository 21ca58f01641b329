// `inbetween play` from the command line: --help, and the arguments it refuses before opening a
// window (exit 2, a message after "inbetween: "); and under Xvfb ("[.window]", run by ctest
// through xvfb-run) the note a one-key scene plays with.
#include "cli_support.h"

#include <catch2/catch.hpp>

using Catch::Contains;
using Catch::StartsWith;
using test::CommandRun;
using test::inbetween;

TEST_CASE("cli: play --help exits 0") {
  const CommandRun run = inbetween({"play", "--help"});
  INFO(run.output);
  CHECK(run.code == 0);
  CHECK(run.err.empty());
  CHECK_THAT(run.out, StartsWith("usage: inbetween play SCENE "));
}

TEST_CASE("cli: play without a scene exits 2") {
  const CommandRun run = inbetween({"play"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: play: needs exactly one SCENE file"));
}

TEST_CASE("cli: play --screenshot without --frames exits 2") {
  const CommandRun run = inbetween({"play", "scene.json", "--screenshot", "shot.png"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: play: --screenshot needs --frames N"));
}

TEST_CASE("cli: play with one key notes that the animation is a still", "[.window]") {
  const CommandRun run = inbetween({"play", test::badScene("one-key.json"), "--frames", "2", "--size", "320x240"});
  INFO(run.output);
  CHECK(run.code == 0);
  CHECK_THAT(run.err, StartsWith("inbetween: note: one-key.json: one key (\"square\"): the animation is a still"));
}
