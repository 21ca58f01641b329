// The command line's arguments: --help, a missing or unknown command, and every benchmark case
// given a bad option value exit with the code the README documents (0, or 2 for bad input), print
// nothing on stdout for bad input, and say on stderr, after "inbetween: ", which word was wrong.
#include "cli_support.h"

#include <catch2/catch.hpp>

using Catch::Contains;
using Catch::StartsWith;
using test::CommandRun;
using test::inbetween;

TEST_CASE("cli: --help exits 0 with the usage on stdout, naming every command") {
  const CommandRun run = inbetween({"--help"});
  INFO(run.output);
  CHECK(run.code == 0);
  CHECK(run.err.empty());
  CHECK_THAT(run.out, StartsWith("usage: inbetween COMMAND [OPTIONS]\n"));
  for (const char* command : {"mesh SCENE", "export SCENE", "new SCENE", "edit SCENE", "parameters", "bench interp", "bench examples"})
    CHECK_THAT(run.out, Contains(std::string("\n  ") + command));
}

TEST_CASE("cli: no command exits 2 with the usage on stderr") {
  const CommandRun run = inbetween({});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("usage: inbetween COMMAND [OPTIONS]\n"));
}

TEST_CASE("cli: unknown command exits 2") {
  const CommandRun run = inbetween({"frobnicate"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: ") && Contains("unknown command 'frobnicate'") && Contains("inbetween --help"));
}

TEST_CASE("cli: unknown bench case exits 2") {
  const CommandRun run = inbetween({"bench", "nosuchcase"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: bench: unknown case 'nosuchcase' (available: interp, comesh, anim"));
}

TEST_CASE("cli: unknown option exits 2") {
  const CommandRun run = inbetween({"bench", "interp", "--bogus"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: bench interp: unknown option --bogus"));
}

TEST_CASE("cli: malformed --sizes exits 2") {
  const CommandRun run = inbetween({"bench", "interp", "--sizes", "abc"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: ") && Contains("--sizes entry 'abc'"));
}

TEST_CASE("cli: --threads out of range exits 2") {
  const CommandRun run = inbetween({"bench", "interp", "--threads", "-3"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: ") && Contains("--threads must be a whole number in [0, 1024], got '-3'"));
}

TEST_CASE("cli: bench comesh with one key exits 2") {
  const CommandRun run = inbetween({"bench", "comesh", "--keys", "1"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: ") && Contains("--keys entry '1' must be in [2, 16]"));
}

TEST_CASE("cli: bench anim with a missing assets folder exits 2") {
  const CommandRun run = inbetween({"bench", "anim", "--assets", "/nonexistent/assets"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: bench anim: --assets: /nonexistent/assets is not a folder"));
}

TEST_CASE("cli: bench anim and mesh with an unknown --scenes name exit 2 naming the nearest scene and every one there") {
  for (const std::string bench : {"anim", "mesh"}) {
    const CommandRun run = inbetween({"bench", bench, "--assets", INBETWEEN_ASSETS, "--scenes", "square-arch-notch,flying-brid"});
    INFO(run.output);
    CHECK(run.code == 2);
    CHECK(run.out.empty());
    CHECK_THAT(run.err, StartsWith("inbetween: bench " + bench + ": --scenes: \"flying-brid\" is not a scene of ") &&
                            Contains("(did you mean \"flying-bird\"?); the scenes there: ") && Contains("square-arch-notch"));
  }
}

TEST_CASE("cli: bench cut with --frames 0 exits 2") {
  const CommandRun run = inbetween({"bench", "cut", "--frames", "0"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: bench cut: --frames must be a whole number in [1, 100000], got '0'"));
}

TEST_CASE("cli: bench shape with an unknown --metric exits 2") {
  const CommandRun run = inbetween({"bench", "shape", "--metric", "harmonic"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: bench shape: --metric: 'harmonic' is not shared, per_key or both"));
}

TEST_CASE("cli: bench examples with an --only that is not an example exits 2") {
  const CommandRun run = inbetween({"bench", "examples", "--only", "no-such-example"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: bench examples: ") && Contains("none of the paper's examples") &&
                          Contains("named no-such-example"));
}
