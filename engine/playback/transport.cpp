#include "playback/transport.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ib::play {

namespace {

// Positions within this many frames of a whole frame count as on it (floating-point sums of
// many small advances).
constexpr double kFrameSlack = 1e-9;

}  // namespace

Transport::Transport(int frameCount, double fps) : frameCount_(frameCount), fps_(fps), out_(frameCount - 1) {
  if (frameCount < 1) throw std::invalid_argument("Transport: frameCount must be at least 1");
  if (!(fps > 0) || !std::isfinite(fps)) throw std::invalid_argument("Transport: fps must be positive");
}

void Transport::play() {
  if (!loop_ && !pingPong_ && frame() >= out_) {
    position_ = in_;
    forward_ = true;
  }
  playing_ = true;
}

void Transport::pause() { playing_ = false; }
void Transport::toggle() { playing_ ? pause() : play(); }
bool Transport::playing() const { return playing_; }

void Transport::step(int frames) {
  playing_ = false;
  const int from = std::clamp(frame(), in_, out_);
  const long long length = static_cast<long long>(out_) - in_ + 1;
  long long to = static_cast<long long>(from) + frames;
  if (loop_) {
    to = in_ + ((to - in_) % length + length) % length;
  } else {
    to = std::clamp<long long>(to, in_, out_);
  }
  position_ = static_cast<double>(to);
  forward_ = true;
}

void Transport::goTo(int frame) {
  position_ = std::clamp(frame, 0, frameCount_ - 1);
  forward_ = true;
}

void Transport::toStart() {
  position_ = in_;
  forward_ = true;
}

void Transport::toEnd() {
  position_ = out_;
  forward_ = true;
}

void Transport::setLoop(bool on) { loop_ = on; }
bool Transport::loop() const { return loop_; }

void Transport::setPingPong(bool on) {
  if (!on && !forward_) {
    position_ = frame();
    forward_ = true;
  }
  pingPong_ = on;
}
bool Transport::pingPong() const { return pingPong_; }

void Transport::setRange(int in, int out) {
  if (in > out) std::swap(in, out);
  in_ = std::clamp(in, 0, frameCount_ - 1);
  out_ = std::clamp(out, 0, frameCount_ - 1);
}
int Transport::in() const { return in_; }
int Transport::out() const { return out_; }

void Transport::setSpeed(double speed) {
  if (std::isfinite(speed)) speed_ = std::clamp(speed, 0.1, 4.0);
}
double Transport::speed() const { return speed_; }

void Transport::enterRange() {
  const int shown = frame();
  if (shown < in_ || shown > out_) {
    position_ = in_;
    forward_ = true;
  } else if (pingPong_) {
    position_ = std::clamp(position_, static_cast<double>(in_), static_cast<double>(out_));
  }
}

int Transport::advance(double seconds) {
  if (!playing_ || !(seconds > 0) || !std::isfinite(seconds)) return frame();
  enterRange();
  const double delta = seconds * speed_ * fps_;
  const double span = out_ - in_;  // frames between the in and the out point
  if (pingPong_) {
    if (span <= 0) {
      position_ = in_;
      if (!loop_) playing_ = false;
      return frame();
    }
    // Unfold the way there and back into one forward distance u in [0, 2 span).
    double u = (forward_ ? position_ - in_ : 2 * span - (position_ - in_)) + delta;
    if (!loop_ && u >= 2 * span) {
      position_ = in_;
      forward_ = true;
      playing_ = false;
      return frame();
    }
    u = std::fmod(u, 2 * span);
    forward_ = u <= span;
    position_ = in_ + (forward_ ? u : 2 * span - u);
  } else if (loop_) {
    position_ = in_ + std::fmod(position_ - in_ + delta, span + 1);
    if (position_ > out_ + 1 - kFrameSlack) position_ = in_;
  } else {
    position_ += delta;
    if (position_ >= out_) {
      position_ = out_;
      playing_ = false;
    }
  }
  return frame();
}

int Transport::frame() const {
  const double whole = forward_ ? std::floor(position_ + kFrameSlack) : std::ceil(position_ - kFrameSlack);
  return std::clamp(static_cast<int>(whole), 0, frameCount_ - 1);
}

double Transport::time() const { return frame() / fps_; }
int Transport::frameCount() const { return frameCount_; }
double Transport::fps() const { return fps_; }
bool Transport::forward() const { return forward_; }

}  // namespace ib::play
