// The player's transport (engine/playback/transport.h): the clock moves speed * seconds * fps
// frames, looping wraps within the range, ping-pong reverses without leaving it, and without
// either the clock stops at the out point.
#include "playback/transport.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

using ib::play::Transport;

TEST_CASE("transport: a new transport is paused at frame 0, looping over every frame at speed 1") {
  const Transport t(48, 24);
  CHECK_FALSE(t.playing());
  CHECK(t.frame() == 0);
  CHECK(t.loop());
  CHECK_FALSE(t.pingPong());
  CHECK(t.in() == 0);
  CHECK(t.out() == 47);
  CHECK(t.speed() == 1);
  CHECK(t.frameCount() == 48);
  CHECK(t.fps() == 24);
}

TEST_CASE("transport: advancing at speed s for t seconds moves s t fps frames, however the time is sliced") {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> slice(0.001, 0.05);
  for (const double speed : {0.25, 1.0, 1.5, 3.0}) {
    Transport t(10000, 24);
    t.setSpeed(speed);
    t.play();
    double elapsed = 0;
    while (elapsed < 10) {
      const double dt = slice(random);
      t.advance(dt);
      elapsed += dt;
    }
    CHECK(t.frame() == static_cast<int>(std::floor(speed * elapsed * 24 + 1e-9)));
  }
}

TEST_CASE("transport: a paused transport does not advance") {
  Transport t(100, 24);
  CHECK(t.advance(1.0) == 0);
  t.play();
  t.pause();
  CHECK(t.advance(1.0) == 0);
}

TEST_CASE("transport: looping wraps within the range and never leaves it") {
  Transport t(100, 10);
  t.setRange(20, 29);
  t.toStart();
  t.play();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> slice(0.01, 0.7);
  double elapsed = 0;
  for (int i = 0; i < 500; ++i) {
    const double dt = slice(random);
    const int frame = t.advance(dt);
    elapsed += dt;
    REQUIRE(frame >= 20);
    REQUIRE(frame <= 29);
    // Ten frames in the range at 10 fps: a period of one second.
    const int expected = 20 + static_cast<int>(std::floor(std::fmod(elapsed * 10, 10.0) + 1e-9)) % 10;
    REQUIRE(frame == expected);
  }
  CHECK(t.playing());
}

TEST_CASE("transport: ping-pong reverses at both ends, shows every frame once per pass and never leaves the range") {
  Transport t(50, 1);
  t.setRange(10, 13);
  t.setPingPong(true);
  t.toStart();
  t.play();
  std::vector<int> frames{t.frame()};
  for (int i = 0; i < 12; ++i) frames.push_back(t.advance(1.0));
  CHECK(frames == std::vector<int>{10, 11, 12, 13, 12, 11, 10, 11, 12, 13, 12, 11, 10});

  std::mt19937 random(3);
  std::uniform_real_distribution<double> slice(0.01, 3.0);
  for (int i = 0; i < 500; ++i) {
    const int frame = t.advance(slice(random));
    REQUIRE(frame >= 10);
    REQUIRE(frame <= 13);
  }
  CHECK(t.playing());
}

TEST_CASE("transport: ping-pong without looping goes out and back once, then stops at the in point") {
  Transport t(20, 1);
  t.setLoop(false);
  t.setPingPong(true);
  t.play();
  t.advance(19.5);
  CHECK(t.frame() == 19);
  CHECK_FALSE(t.forward());
  t.advance(100);
  CHECK(t.frame() == 0);
  CHECK_FALSE(t.playing());
}

TEST_CASE("transport: without looping the clock stops at the out point, and play starts again from the in point") {
  Transport t(30, 24);
  t.setLoop(false);
  t.setRange(5, 15);
  t.toStart();
  t.play();
  CHECK(t.advance(100) == 15);
  CHECK_FALSE(t.playing());
  CHECK(t.advance(1) == 15);
  t.play();
  CHECK(t.frame() == 5);
  CHECK(t.playing());
}

TEST_CASE("transport: stepping pauses and wraps within the range when looping, clamps otherwise") {
  Transport t(100, 24);
  t.setRange(10, 19);
  t.toStart();
  t.play();
  t.step(-1);
  CHECK_FALSE(t.playing());
  CHECK(t.frame() == 19);
  t.step(3);
  CHECK(t.frame() == 12);
  t.step(-25);
  CHECK(t.frame() == 17);
  t.setLoop(false);
  t.step(100);
  CHECK(t.frame() == 19);
  t.step(-100);
  CHECK(t.frame() == 10);
}

TEST_CASE("transport: goTo clamps to the timeline and keeps playing, toStart and toEnd go to the range's points") {
  Transport t(60, 24);
  t.setRange(40, 20);  // swapped into order
  CHECK(t.in() == 20);
  CHECK(t.out() == 40);
  t.play();
  t.goTo(1000);
  CHECK(t.frame() == 59);
  CHECK(t.playing());
  t.goTo(-5);
  CHECK(t.frame() == 0);
  t.toEnd();
  CHECK(t.frame() == 40);
  t.toStart();
  CHECK(t.frame() == 20);
  CHECK(t.playing());
  t.setRange(-10, 500);
  CHECK(t.in() == 0);
  CHECK(t.out() == 59);
}

TEST_CASE("transport: playing from outside the range goes to its in point first") {
  Transport t(60, 10);
  t.setRange(20, 30);
  t.goTo(50);
  t.play();
  CHECK(t.advance(0.05) == 20);
}

TEST_CASE("transport: speed is clamped to [0.1, 4]") {
  Transport t(10, 24);
  t.setSpeed(10);
  CHECK(t.speed() == 4);
  t.setSpeed(0);
  CHECK(t.speed() == Approx(0.1).margin(1e-12));
  t.setSpeed(-3);
  CHECK(t.speed() == Approx(0.1).margin(1e-12));
  t.setSpeed(std::nan(""));
  CHECK(t.speed() == Approx(0.1).margin(1e-12));
  t.setSpeed(2);
  CHECK(t.speed() == 2);
}

TEST_CASE("transport: time() is the frame's time on the timeline") {
  Transport t(100, 24);
  t.goTo(36);
  CHECK(t.time() == Approx(1.5).margin(1e-12));
}

TEST_CASE("transport: a timeline of one frame stays on it in every mode") {
  Transport t(1, 24);
  t.play();
  CHECK(t.advance(5) == 0);
  t.setPingPong(true);
  CHECK(t.advance(5) == 0);
  t.step(3);
  CHECK(t.frame() == 0);
}

TEST_CASE("transport: turning ping-pong on at the out point reverses from there") {
  Transport t(10, 1);
  t.play();
  CHECK(t.advance(9.5) == 9);
  t.setPingPong(true);
  CHECK(t.advance(0.75) == 9);
  CHECK(t.advance(1) == 8);
  t.setPingPong(false);  // forward again from the frame shown
  CHECK(t.frame() == 8);
  CHECK(t.advance(1) == 9);
}
